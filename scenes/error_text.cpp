#include "scenes/error_text.h"

#include <cstdio>

namespace shadowlab {
namespace {

std::string escaped(std::string_view text, bool quotes) {
    std::string out;
    for (const char c : text) {
        const auto byte = static_cast<unsigned char>(c);
        if (c == '\n') out += "\\n";
        else if (c == '\r') out += "\\r";
        else if (c == '\t') out += "\\t";
        else if (byte < 0x20 || byte == 0x7f) {
            char hex[5];
            std::snprintf(hex, sizeof hex, "\\x%02x", unsigned(byte));
            out += hex;
        } else if (quotes && (c == '"' || c == '\\')) out += {'\\', c};
        else out += c;
    }
    return out;
}

}  // namespace

std::string oneLine(std::string_view text) { return escaped(text, false); }

std::string inQuotes(std::string_view text) {
    std::string out(1, '"');   // appended, not chained: GCC 12 warns wrongly of a chain of string +
    out += escaped(text, true);
    out += '"';
    return out;
}

}  // namespace shadowlab
