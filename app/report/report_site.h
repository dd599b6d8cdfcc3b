// `shadowlab report`: a static HTML site of sweep and render results, readable from
// file:// with nothing fetched from elsewhere (docs/report.md). Its stages: the inputs
// collected (report_collect.h), the pages drawn (report_pages.h), and the site written
// whole with the stylesheet and script the program carries (report_assets.h).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "app/plots/sweep_plot.h"

namespace shadowlab {

// collectReport(), then index.html, a page per scene and per setting, report.css and
// report.js, all in outDir (created if missing), whole or not at all (staged_outputs.h).
// The files written are listed in outDir/report-files.txt; what the last report listed
// and this one did not write (the stale pages of another sweep) is removed. Returns the
// number of pages.
size_t writeReportSite(const std::vector<std::string>& files, const std::filesystem::path& outDir,
                       PlotErrorAxis plotY);

}  // namespace shadowlab
