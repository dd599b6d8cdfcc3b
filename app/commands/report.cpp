// `shadowlab report`: the static HTML site of sweep and render results (app/report/).
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/commands/commands.h"
#include "app/plots/sweep_plot.h"
#include "app/report/report_site.h"

namespace shadowlab {
namespace {

struct ReportArgs {
    std::vector<std::string> files;
    std::string outDir = "out/report", plotY = "auto";
};

void runReportCommand(const ReportArgs& a) {
    const size_t pages = writeReportSite(a.files, a.outDir, parsePlotErrorAxis(a.plotY));
    std::cout << "wrote " << pages << " pages: " << (std::filesystem::path(a.outDir) / "index.html").string()
              << "\n";
}

}  // namespace

void addReportCommand(CLI::App& command) {
    ReportArgs& a = argumentsRunBy<ReportArgs>(command, runReportCommand);
    CLI::App* r = command.description("a static HTML site of sweep and render --error-map --json results, "
                                      "read from file:// (index, a page per scene and per setting)");
    r->add_option("files", a.files, "JSON files of sweep (with --images for pictures) or of render --error-map --json")
        ->required();
    r->add_option("--out", a.outDir, "directory for index.html and the rest of the site")->capture_default_str();
    r->add_option("--plot-y", a.plotY, "the plots' error axis, as sweep's --plot-y")->capture_default_str();
}

}  // namespace shadowlab
