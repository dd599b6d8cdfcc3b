// The report's stylesheet and script, app/report/report.css and report.js, carried in the
// program (app/CMakeLists.txt embeds them at build time), so that an installed shadowlab
// writes them into a report without its source tree.
#pragma once

#include <string_view>

namespace shadowlab {

extern const std::string_view kReportCss;
extern const std::string_view kReportJs;

}  // namespace shadowlab
