// Text in error messages. Every error is one line (docs/reliability.md, "Reliability"): a name or a
// path the user wrote is quoted with its control characters escaped, so that a newline in
// a JSON key or a file name cannot split the message, and the printer escapes whatever
// control character is left.
#pragma once

#include <string>
#include <string_view>

namespace shadowlab {

// text with \n, \r, \t and every other control character (\xHH) escaped.
std::string oneLine(std::string_view text);

// text in double quotes, with quotes and backslashes escaped as well: "a \"b\"\n".
std::string inQuotes(std::string_view text);

}  // namespace shadowlab
