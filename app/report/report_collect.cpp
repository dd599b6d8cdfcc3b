#include "app/report/report_collect.h"

#include <algorithm>
#include <fstream>
#include <map>
#include <set>
#include <stdexcept>
#include <tuple>
#include <utility>
#include <variant>

#include "app/measure/sweep_json.h"
#include "frame/registry.h"
#include "scenes/read_file.h"
#include "shading/image_io.h"
#include "shadows/technique.h"

namespace shadowlab {
namespace {

// A render's JSON lists every parameter: its page names only those off the technique's
// defaults, as a sweep's rows do (all of them for a technique this build does not know).
void dropDefaults(SweepRow& row) {
    const auto technique = std::ranges::find(techniques(), row.technique, &Technique::name);
    if (technique == techniques().end()) return;
    for (const ParamSpec& param : technique->params) {
        const auto setting = row.settings.find(param.name);
        if (setting != row.settings.end() && setting->second == param.defaultValue) row.settings.erase(setting);
    }
}

// A render's JSON as a sweep of one row, so that every page treats both alike.
SweepResults renderAsSweep(ScoreRecord record) {
    dropDefaults(record.row);
    SweepResults results;
    results.scene = record.scene;
    results.techniques = {record.row.technique};
    results.grid.overrides = record.overrides.value_or(SceneOverrides{});
    results.rows = {std::move(record.row)};
    return results;
}

ReportSource readSource(const std::string& file) {
    std::variant<SweepResults, ScoreRecord> parsed = parseResultsJson(readWholeFile(file), file);
    ReportSource source;
    source.file = file;
    source.render = std::holds_alternative<ScoreRecord>(parsed);
    const bool recorded = !source.render || std::get<ScoreRecord>(parsed).overrides.has_value();
    source.results = source.render ? renderAsSweep(std::get<ScoreRecord>(std::move(parsed)))
                                   : std::get<SweepResults>(std::move(parsed));
    source.conditions = recorded ? describeOverrides(source.results.grid.overrides)
                                 : "conditions not recorded (a render's JSON from before they were)";
    return source;
}

// The stem, or stem-2, stem-3, ... if it is taken.
std::string uniqueName(const std::string& stem, std::set<std::string>& taken) {
    std::string name = stem;
    for (int k = 2; !taken.insert(name).second; ++k) name = stem + "-" + std::to_string(k);
    return name;
}

// The rows of one sweep setting (one per thread count) share a page.
void planSettings(ReportSource& source) {
    std::map<uint64_t, size_t> pageOf;   // setting -> index in source.settings
    for (size_t k = 0; k < source.results.rows.size(); ++k) {
        const uint64_t setting = source.results.rows[k].setting;
        const auto [at, added] = pageOf.emplace(setting, source.settings.size());
        if (added) source.settings.push_back({source.name + "-setting-" + std::to_string(setting) + ".html", {}});
        source.settings[at->second].rows.push_back(k);
    }
}

// Where a picture goes in the site: images/SOURCE/ and then its path in the JSON, each part
// made safe ('..' becomes 'up'), so that a picture several rows share (a reference's) is
// copied once. Making names safe can make two alike ("a b.png", "a-b.png"): copyPictures
// then gives the second another name.
std::filesystem::path sitePath(const std::string& sourceName, const std::string& relative) {
    std::filesystem::path site = std::filesystem::path("images") / sourceName;
    for (const std::filesystem::path& part : std::filesystem::path(relative).lexically_normal().relative_path())
        if (!part.empty()) site /= part == ".." ? "up" : safeFileName(part.string());
    return site;
}

// `site`, or if another picture holds it, the first of SITE-2, SITE-3, ... (before the
// extension) that is free or holds this picture.
std::filesystem::path freeSitePath(const std::filesystem::path& site, const std::filesystem::path& picture,
                                   const std::map<std::filesystem::path, std::filesystem::path>& copies) {
    const auto same = [](const std::filesystem::path& a, const std::filesystem::path& b) {
        return std::filesystem::absolute(a).lexically_normal() == std::filesystem::absolute(b).lexically_normal();
    };
    std::filesystem::path candidate = site;
    for (int k = 2;; ++k) {
        const auto taken = copies.find(candidate);
        if (taken == copies.end() || same(taken->second, picture)) return candidate;
        candidate = site.parent_path() / (site.stem().string() + "-" + std::to_string(k) + site.extension().string());
    }
}

// Every picture of every row, from beside its JSON to its place in the site; the rows then
// name them relative to the site. All are checked before any is copied.
void copyPictures(std::vector<ReportSource>& sources, const std::filesystem::path& outDir) {
    std::map<std::filesystem::path, std::filesystem::path> copies;   // site path -> picture
    for (ReportSource& source : sources) {
        const std::filesystem::path jsonDir = std::filesystem::path(source.file).parent_path();
        for (SweepRow& row : source.results.rows) {
            row.images = withPaths(row.images, [&](const std::string& relative) {
                const std::filesystem::path picture = jsonDir / relative;
                if (!std::filesystem::is_regular_file(picture))
                    throw std::runtime_error(source.file + ": picture '" + relative + "' not found (no file " +
                                             picture.string() + ")");
                const std::filesystem::path site = freeSitePath(sitePath(source.name, relative), picture, copies);
                copies.emplace(site, picture);
                return site.generic_string();
            });
        }
    }
    for (const auto& [site, picture] : copies) {
        std::filesystem::create_directories((outDir / site).parent_path());
        std::filesystem::copy_file(picture, outDir / site, std::filesystem::copy_options::overwrite_existing);
    }
}

// Width and height from a PNG's header (its IHDR chunk, bytes 16 to 23, big-endian);
// {0, 0} for a file that is not a PNG.
std::pair<int, int> pngSize(const std::filesystem::path& path) {
    std::string head(24, '\0');
    std::ifstream file(path, std::ios::binary);
    if (!file.read(head.data(), std::streamsize(head.size())) || head.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0)
        return {0, 0};
    const auto bigEndian = [&](size_t at) {
        uint32_t value = 0;
        for (size_t k = at; k < at + 4; ++k) value = value << 8 | uint8_t(head[k]);
        return int(std::min<uint32_t>(value, 1u << 30));
    };
    return {bigEndian(16), bigEndian(20)};
}

// Each setting's picture size, for the zoom: its image's, or its error map's.
void measurePictures(std::vector<ReportSource>& sources, const std::filesystem::path& outDir) {
    for (ReportSource& source : sources) {
        for (ReportSetting& setting : source.settings) {
            const FrameImages& images = source.results.rows[setting.rows.front()].images;
            const std::string& picture = images.image.empty() ? images.errorMap : images.image;
            if (!picture.empty()) std::tie(setting.width, setting.height) = pngSize(outDir / picture);
        }
    }
}

// Scenes under their conditions in the order they first appear, each with its sources.
std::vector<ReportScene> groupScenes(const std::vector<ReportSource>& sources, std::set<std::string>& taken) {
    std::vector<ReportScene> scenes;
    for (size_t k = 0; k < sources.size(); ++k) {
        const std::string& name = sources[k].results.scene;
        const std::string& conditions = sources[k].conditions;
        auto scene = std::ranges::find_if(scenes, [&](const ReportScene& s) { return s.name == name && s.conditions == conditions; });
        if (scene == scenes.end())
            scene = scenes.insert(scenes.end(),
                                  {name, uniqueName("scene-" + safeFileName(name), taken) + ".html", conditions, {}});
        scene->sources.push_back(k);
    }
    return scenes;
}
}  // namespace

std::string safeFileName(const std::string& text) {
    std::string safe = text;
    for (char& c : safe) {
        const bool kept = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' ||
                          c == '_' || c == '+' || c == '-';
        if (!kept) c = '-';
    }
    return safe.empty() || safe.front() == '.' ? "-" + safe : safe;
}

ReportSite collectReport(const std::vector<std::string>& files, const std::filesystem::path& outDir,
                         PlotErrorAxis plotY) {
    if (files.empty())
        throw std::invalid_argument("report: give the JSON files of sweeps or of render --error-map --json");
    ReportSite site;
    site.plotY = plotY;
    std::set<std::string> taken = {"index", "images", "report"};   // the site's other names
    for (const std::string& file : files) {
        ReportSource& source = site.sources.emplace_back(readSource(file));
        try {
            requirePlottable(source.results.rows, plotY);
        } catch (const std::invalid_argument& error) {
            throw std::runtime_error(file + ": " + error.what());
        }
        source.name = uniqueName(safeFileName(std::filesystem::path(file).stem().string()), taken);
        planSettings(source);
    }
    site.scenes = groupScenes(site.sources, taken);
    copyPictures(site.sources, outDir);
    measurePictures(site.sources, outDir);
    return site;
}

}  // namespace shadowlab
