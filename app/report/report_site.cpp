#include "app/report/report_site.h"

#include <set>
#include <sstream>

#include "app/common/staged_outputs.h"
#include "app/report/report_assets.h"
#include "app/report/report_pages.h"
#include "scenes/read_file.h"
#include "scenes/write_file.h"

namespace shadowlab {
namespace {

// The list of a report's files, kept in its folder so that the next report into the same
// folder can remove the pages this one wrote and that one does not.
constexpr const char* kListing = "report-files.txt";

std::set<std::string> listedFiles(const std::filesystem::path& outDir) {
    std::set<std::string> names;
    std::error_code missing;
    if (!std::filesystem::is_regular_file(outDir / kListing, missing)) return names;
    std::istringstream lines(readWholeFile((outDir / kListing).string()));
    for (std::string line; std::getline(lines, line);)
        if (!line.empty()) names.insert(line);
    return names;
}

// Removes what the last report listed and this one did not write, and folders so emptied.
// A listed name that leaves the folder ("..", an absolute path) is not the report's: kept.
void removeStale(const std::filesystem::path& outDir, const std::set<std::string>& before, const std::set<std::string>& written) {
    std::error_code ignored;
    for (const std::string& name : before) {
        const std::filesystem::path relative = std::filesystem::path(name).lexically_normal();
        if (written.contains(name) || relative.is_absolute() || relative.empty() || *relative.begin() == "..") continue;
        std::filesystem::remove(outDir / relative, ignored);
        for (std::filesystem::path folder = relative.parent_path(); !folder.empty(); folder = folder.parent_path())
            if (!std::filesystem::remove(outDir / folder, ignored)) break;   // only if empty
    }
}

}  // namespace

size_t writeReportSite(const std::vector<std::string>& files, const std::filesystem::path& outDir,
                       PlotErrorAxis plotY) {
    StagedOutputs outputs(outDir);
    const std::filesystem::path& staging = outputs.folder();
    const ReportSite site = collectReport(files, staging, plotY);   // every input read before a page is written
    writeTextFile(staging / "report.css", kReportCss);
    writeTextFile(staging / "report.js", kReportJs);
    std::vector<std::pair<std::string, std::string>> pages = {{"index.html", indexPage(site)}};
    for (const ReportScene& scene : site.scenes) pages.emplace_back(scene.page, scenePage(site, scene));
    for (const ReportSource& source : site.sources)
        for (const ReportSetting& setting : source.settings)
            pages.emplace_back(setting.page, settingPage(site, source, setting));
    for (const auto& [name, html] : pages) writeTextFile(staging / name, html);
    const std::set<std::string> before = listedFiles(outDir);
    std::string listing;
    std::set<std::string> written;
    for (const std::filesystem::directory_entry& entry : std::filesystem::recursive_directory_iterator(staging)) {
        if (entry.is_directory()) continue;
        written.insert(std::filesystem::relative(entry.path(), staging).generic_string());
    }
    written.insert(kListing);
    for (const std::string& name : written) listing += name + "\n";
    writeTextFile(staging / kListing, listing);
    outputs.commit();
    removeStale(outDir, before, written);
    return pages.size();
}

}  // namespace shadowlab
