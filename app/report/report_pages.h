// The report's pages as HTML (report_collect.h collects what they show). Each stands without
// JavaScript: pictures side by side, plain tables, plots whose points are links;
// report.js adds the before/after slider and sorting by any column. The zoom (whole
// pixels, `image-rendering: pixelated`) is CSS alone.
#pragma once

#include <string>

#include "app/report/report_collect.h"

namespace shadowlab {

// The scenes and the techniques, each linking down to its pages.
std::string indexPage(const ReportSite& site);

// Per input file of the scene: the speed-against-error plot, every point a link to its
// setting's page, and the rows as a sortable table (with each light's misclassified % and
// RMS for a scene of several lights).
std::string scenePage(const ReportSite& site, const ReportScene& scene);

// One setting: its image, the reference and the error map (and V), the slider between the
// image and the reference, the error figures (and each light's), the times, the stats and
// the debug buffers (under a heading per light for a frame of several).
std::string settingPage(const ReportSite& site, const ReportSource& source, const ReportSetting& setting);

}  // namespace shadowlab
