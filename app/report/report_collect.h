// `shadowlab report`, its first stage: the inputs read (sweep JSONs, and render --error-map
// --json files, each a sweep of one row), grouped by scene and conditions, every setting
// given a page name and its pictures copied into the site. The pages (report_pages.h) are
// drawn from what this collects; report_site.h writes them.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "app/measure/sweep.h"
#include "app/plots/sweep_plot.h"

namespace shadowlab {

// One setting on its own page: the rows of one sweep setting (one per thread count), or
// the one row of a render.
struct ReportSetting {
    std::string page;           // its file name in the site
    std::vector<size_t> rows;   // indices into ReportSource::results.rows
    int width = 0, height = 0;  // of its image or error map, read from the PNG (0: it has neither)
};

// One input file.
struct ReportSource {
    std::string file;                      // as given
    std::string name;                      // its stem, made unique in the site and safe in a URL
    bool render = false;                   // render --error-map --json, not a sweep
    SweepResults results;                  // the rows' pictures relative to the site's directory
    std::string conditions;                // describeOverrides(), or that they were not recorded
    std::vector<ReportSetting> settings;   // in the order of their first rows
};

// The results of one scene under one set of conditions (its overrides of image size, view
// and light): results measured under other conditions are not comparable, so each set has
// its own page.
struct ReportScene {
    std::string name, page;
    std::string conditions;        // describeOverrides() of its sources' overrides
    std::vector<size_t> sources;   // indices into ReportSite::sources, in the order given
};

struct ReportSite {
    std::vector<ReportSource> sources;
    std::vector<ReportScene> scenes;   // in the order they first appear
    PlotErrorAxis plotY = PlotErrorAxis::Auto;
};

// `text` with every character but letters, digits, '.', '_', '+' and '-' replaced by '-':
// a file name that needs no escaping in a URL or in HTML.
std::string safeFileName(const std::string& text);

// Reads each file (a sweep's JSON or a render's, told apart by their fields), names the
// pages and copies every picture the rows name (relative to their JSON) into
// outDir/images/SOURCE/. Throws std::runtime_error naming the file: one that is neither
// kind, a missing picture, a plot axis a row has no figure for.
ReportSite collectReport(const std::vector<std::string>& files, const std::filesystem::path& outDir,
                         PlotErrorAxis plotY);

}  // namespace shadowlab
