// The pieces of HTML every page of the report is made of: the page's frame, table cells
// that sort by their numbers, figures. Text and attribute values from the inputs (scene,
// technique, setting and stat names) are escaped with svg::escape, whose four entities
// are HTML's too; file names in the site need none (safeFileName()).
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "app/plots/svg.h"

namespace shadowlab::html {

using svg::escape;

// A whole page: the stylesheet and the deferred script of the site, `trail` (links up to
// the index) above the title, then the body.
inline std::string page(const std::string& title, const std::string& trail, const std::string& body) {
    return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
           "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>" + escape(title) +
           "</title>\n<link rel=\"stylesheet\" href=\"report.css\">\n<script src=\"report.js\" defer></script>\n"
           "</head>\n<body>\n<nav class=\"trail\">" + trail + "</nav>\n<main>\n<h1>" + escape(title) + "</h1>\n" +
           body + "</main>\n</body>\n</html>\n";
}

inline std::string link(const std::string& href, const std::string& text) {
    return "<a href=\"" + escape(href) + "\">" + escape(text) + "</a>";
}

// A number in `format` (printf), with its exact value in data-value for sorting; a NaN is
// "n/a" and sorts last.
inline std::string numberCell(double value, const char* format) {
    if (std::isnan(value)) return "<td class=\"number\" data-value=\"\">n/a</td>";
    return svg::format("<td class=\"number\" data-value=\"%.17g\">", value) + svg::format(format, value) + "</td>";
}

inline std::string cell(const std::string& html) { return "<td>" + html + "</td>"; }

// A table whose rows report.js sorts by any column (plain without JavaScript).
inline std::string sortableTable(const std::vector<std::string>& columns, const std::string& rows) {
    std::string header;
    for (const std::string& column : columns) header += "<th scope=\"col\">" + escape(column) + "</th>";
    return "<table class=\"sortable\">\n<thead><tr>" + header + "</tr></thead>\n<tbody>\n" + rows +
           "</tbody>\n</table>\n";
}

}  // namespace shadowlab::html
