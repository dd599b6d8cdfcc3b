// printf into a std::string, for the tables, file names and SVG the commands write.
#pragma once

#include <cstdio>
#include <string>

namespace shadowlab::text {

std::string format(const char* pattern, auto... values) {
    std::string text(size_t(std::snprintf(nullptr, 0, pattern, values...)), '\0');
    std::snprintf(text.data(), text.size() + 1, pattern, values...);
    return text;
}

}  // namespace shadowlab::text
