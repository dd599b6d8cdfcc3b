// Text in error messages stays one line (scenes/error_text.h): quoted names escape quotes,
// backslashes and control characters; the printer's pass escapes control characters only.
#include <doctest/doctest.h>

#include "scenes/error_text.h"

using namespace shadowlab;

TEST_CASE("error text: a quoted name or a printed message holds no line break or control character") {
    CHECK(inQuotes("mesh") == "\"mesh\"");
    CHECK(inQuotes("a \"b\"\\") == "\"a \\\"b\\\"\\\\\"");
    CHECK(inQuotes(std::string("bo\nx\r\t\x1b[31m\x7f", 12)) == "\"bo\\nx\\r\\t\\x1b[31m\\x7f\"");
    CHECK(inQuotes("d\xc3\xa9j\xc3\xa0") == "\"d\xc3\xa9j\xc3\xa0\"");   // UTF-8 passes as it is
    CHECK(oneLine("scene.json: unknown key \"a\"\n") == "scene.json: unknown key \"a\"\\n");
    CHECK(oneLine(std::string("\0", 1)) == "\\x00");
}
