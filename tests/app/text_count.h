// How many times a pattern occurs in a text (overlapping occurrences counted), for the tests
// of the SVG and text outputs.
#pragma once

#include <cstddef>
#include <string>

namespace shadowlab::test {

inline size_t countOf(const std::string& text, const std::string& pattern) {
    size_t n = 0;
    for (size_t at = text.find(pattern); at != std::string::npos; at = text.find(pattern, at + 1)) ++n;
    return n;
}

}  // namespace shadowlab::test
