#include "app/measure/flythrough_report.h"

#include <algorithm>

#include <nlohmann/json.hpp>

#include "app/common/csv.h"
#include "app/common/text_format.h"
#include "app/measure/sweep_json.h"

namespace shadowlab {
namespace {

using Json = nlohmann::ordered_json;

std::vector<std::string> vectorFields(const std::optional<glm::vec3>& v) {
    if (!v) return {"", "", ""};
    return {csvNumber(v->x), csvNumber(v->y), csvNumber(v->z)};
}

Json frameJson(const FlythroughFrame& f) {
    Json frame = {{"frame", f.frame}, {"time", f.time}, {"eye", xyz(f.eye)}, {"target", xyz(f.target)}};
    if (f.light) frame["light"] = xyz(*f.light);
    frame["median_ms"] = f.medianMs;
    frame["min_ms"] = f.minMs;
    frame["moved"] = f.moved;
    frame["errors"] = Json::parse(formatJson(f.errors));
    Json stats = Json::object();
    for (const TechniqueStat& stat : f.stats) stats[stat.name] = stat.value;
    frame["stats"] = stats;
    frame["flicker"] = f.flicker ? Json{{"mean", f.flicker->mean}, {"p99", f.flicker->p99},
                                        {"pixels", f.flicker->pixels}, {"stable_pixels", f.flicker->stablePixels}}
                                 : Json(nullptr);
    return frame;
}

Json seriesJson(const FlythroughSeries& s) {
    const PathFigures p = pathFigures(s);
    Json frames = Json::array();
    for (const FlythroughFrame& f : s.frames) frames.push_back(frameJson(f));
    return {{"technique", s.technique}, {"reference", s.reference}, {"settings", s.settings},
            {"path_figures", {{"median_ms", p.medianMs}, {"mean_rms", p.meanRms}, {"mean_flip", p.meanFlip},
                              {"mean_misclassified_percent", p.meanMisclassifiedPercent},
                              {"flicker_mean", p.flickerMean}, {"flicker_p99", p.flickerP99},
                              {"settle_frames", p.settleFrames ? Json(*p.settleFrames) : Json(nullptr)},
                              {"settled", p.settleFrames ? Json(p.settled) : Json(nullptr)},
                              {"ghosting_rms_frames", p.ghosting ? Json(*p.ghosting) : Json(nullptr)}}},
            {"frames", frames}};
}

// Every stat name any frame of any series reports, in the order first seen: the CSV's last
// columns, blank where a frame has no such figure.
std::vector<std::string> statColumns(const FlythroughResults& results) {
    std::vector<std::string> names;
    for (const FlythroughSeries& s : results.series)
        for (const FlythroughFrame& f : s.frames)
            for (const TechniqueStat& stat : f.stats)
                if (std::find(names.begin(), names.end(), stat.name) == names.end()) names.push_back(stat.name);
    return names;
}

}  // namespace

std::string formatFlythroughText(const FlythroughResults& results) {
    using text::format;
    std::string text = format("%s: %d frames of path %s, %d threads, median of %d runs after %d warm-up\n",
                              results.scene.c_str(), results.frames, results.path.c_str(), results.threads,
                              results.runs, results.warmupRuns);
    text += format("%-36s %10s %10s %10s %8s %13s %12s %7s %9s\n", "series", "median ms", "mean RMS", "mean FLIP",
                   "miscl %", "flicker mean", "flicker p99", "settle", "ghosting");
    for (const FlythroughSeries& s : results.series) {
        const PathFigures p = pathFigures(s);
        // "13+": still converging at the path's end.
        const std::string settle =
            p.settleFrames ? std::to_string(*p.settleFrames) + (p.settled ? "" : "+") : std::string("-");
        const std::string ghosting = p.ghosting ? format("%.5f", *p.ghosting) : "-";
        text += format("%-36s %10.3f %10.5f %10.5f %8.3f %13.6f %12.5f %7s %9s\n", s.label().c_str(), p.medianMs,
                       p.meanRms, p.meanFlip, p.meanMisclassifiedPercent, p.flickerMean, p.flickerP99, settle.c_str(),
                       ghosting.c_str());
    }
    return text;
}

std::string formatFlythroughCsv(const FlythroughResults& results) {
    const std::vector<std::string> stats = statColumns(results);
    std::vector<std::string> header{"technique", "settings", "frame", "time", "eye_x", "eye_y", "eye_z", "target_x",
                                    "target_y", "target_z", "light_x", "light_y", "light_z", "median_ms", "min_ms", "rms",
                                    "max_abs", "misclassified_percent", "false_shadow_percent", "false_light_percent",
                                    "flip_mean", "flicker_mean", "flicker_p99", "flicker_stable_percent", "moved"};
    header.insert(header.end(), stats.begin(), stats.end());
    std::string csv = csvLine(header);
    for (const FlythroughSeries& s : results.series) {
        for (const FlythroughFrame& f : s.frames) {
            std::vector<std::string> fields{s.technique, settingsLabel(s.settings), std::to_string(f.frame),
                                            csvNumber(f.time)};
            for (const auto& v : {std::optional(f.eye), std::optional(f.target), f.light}) {
                const std::vector<std::string> three = vectorFields(v);
                fields.insert(fields.end(), three.begin(), three.end());
            }
            const ErrorFigures& e = f.errors;
            for (double x : {f.medianMs, f.minMs, e.rms, e.maxAbs, e.percentOfPixels(e.misclassified()),
                             e.percentOfPixels(e.falseShadow), e.percentOfPixels(e.falseLight)})
                fields.push_back(csvNumber(x));
            fields.push_back(e.flipMean ? csvNumber(*e.flipMean) : "");
            if (!f.flicker) fields.insert(fields.end(), 3, "");   // frame 0 has nothing to differ from
            else
                for (double x : {f.flicker->mean, f.flicker->p99, f.flicker->stablePercent()})
                    fields.push_back(csvNumber(x));
            fields.push_back(f.moved ? "1" : "0");
            for (const std::string& name : stats) {
                const auto stat = std::ranges::find(f.stats, name, &TechniqueStat::name);
                fields.push_back(stat == f.stats.end() ? "" : csvNumber(stat->value));
            }
            csv += csvLine(fields);
        }
    }
    return csv;
}

std::string formatFlythroughJson(const FlythroughResults& results) {
    Json series = Json::array();
    for (const FlythroughSeries& s : results.series) series.push_back(seriesJson(s));
    const Json json = {{"scene", results.scene}, {"path", results.path}, {"frames", results.frames},
                       {"threads", results.threads}, {"warmup", results.warmupRuns}, {"runs", results.runs},
                       {"stable_tolerance", results.stableTolerance}, {"series", series}};
    return json.dump(1) + "\n";
}

}  // namespace shadowlab
