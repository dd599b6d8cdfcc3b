// The fields of one line of a sweep's CSV, for the tests that read it back.
#pragma once

#include <string>
#include <vector>

namespace shadowlab::test {

// Fields of an unquoted CSV line; "a,," has three, the last two empty (RFC 4180).
inline std::vector<std::string> splitCsvLine(const std::string& line) {
    std::vector<std::string> fields(1);
    for (char c : line) {
        if (c == ',') fields.emplace_back();
        else fields.back() += c;
    }
    return fields;
}

}  // namespace shadowlab::test
