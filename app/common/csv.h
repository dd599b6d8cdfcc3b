// CSV as every command writes it (sweep, scaling, flythrough): one RFC 4180 line (fields
// with a comma, quote or line break quoted), and a number with 9 significant digits.
#pragma once

#include <string>
#include <vector>

namespace shadowlab {

std::string csvLine(const std::vector<std::string>& fields);
std::string csvNumber(double value);

}  // namespace shadowlab
