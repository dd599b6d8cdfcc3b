#include "app/sweep.h"

#include <algorithm>
#include <cstdio>
#include <iterator>
#include <memory>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>
#include <tbb/global_control.h>
#include <tbb/info.h>

#include "app/render.h"
#include "app/score.h"
#include "app/timing.h"
#include "scenes/scene_file.h"

namespace shadowlab {
namespace {

using Settings = std::map<std::string, std::string>;

// One technique with the settings it is swept over.
struct SweepPlan {
    const Technique* technique;
    std::vector<Settings> settings;
};

bool hasParam(const Technique& technique, const std::string& name) {
    return std::ranges::any_of(technique.params, [&](const ParamSpec& p) { return p.name == name; });
}

// Every combination of the axes' values, the first axis varying slowest.
std::vector<Settings> crossProduct(const std::vector<SweepAxis>& axes) {
    std::vector<Settings> combinations{{}};
    for (const SweepAxis& axis : axes) {
        std::vector<Settings> next;
        for (const Settings& partial : combinations) {
            for (const std::string& value : axis.values) {
                Settings extended = partial;
                extended[axis.name] = value;
                next.push_back(std::move(extended));
            }
        }
        combinations = std::move(next);
    }
    return combinations;
}

// Each technique gets the axes it has; every axis must belong to at least one technique,
// or it was a typo.
std::vector<SweepPlan> planSweep(const SweepOptions& options) {
    std::vector<SweepPlan> plans;
    for (const Technique* technique : options.techniques) {
        if (std::ranges::any_of(plans, [&](const SweepPlan& p) { return p.technique->name == technique->name; }))
            throw std::invalid_argument("technique '" + technique->name + "' is listed twice");
        std::vector<SweepAxis> axes;
        std::ranges::copy_if(options.axes, std::back_inserter(axes), [&](const SweepAxis& a) { return hasParam(*technique, a.name); });
        plans.push_back({technique, crossProduct(axes)});
    }
    for (const SweepAxis& axis : options.axes) {
        if (std::ranges::none_of(plans, [&](const SweepPlan& p) { return hasParam(*p.technique, axis.name); }))
            throw std::invalid_argument("--param " + axis.name + ": none of the techniques has this parameter (see `shadowlab techniques`)");
    }
    return plans;
}

std::vector<int> threadCounts(const SweepOptions& options) {
    if (options.threads.empty()) return {tbb::info::default_concurrency()};
    for (int n : options.threads)
        if (n < 1) throw std::invalid_argument("thread counts must be at least 1, got " + std::to_string(n));
    return options.threads;
}

// Warm-up frames, then the measured ones; errors and stats come from the last frame.
SweepRow measure(const Scene& scene, const WorldGeometry& world, const ImageChannels& reference,
                 const Technique& technique, const FrameSettings& settings, const SweepOptions& options) {
    for (int k = 0; k < options.warmupRuns; ++k) renderFrame(scene, world, technique, settings);
    std::vector<double> ms;
    Frame frame;
    for (int k = 0; k < options.runs; ++k) {
        frame = renderFrame(scene, world, technique, settings);
        ms.push_back(frame.techniqueMs);
    }
    const Timing timing = summarizeTimes(std::move(ms));
    SweepRow row;
    row.technique = technique.name;
    row.settings = settings.params;
    row.medianMs = timing.medianMs;
    row.minMs = timing.minMs;
    row.errors = scoreFrame(reference, frame);
    row.stats = frame.shadow.stats;
    return row;
}

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", value);
    return text;
}

// RFC 4180: a field with a comma, quote or line break is quoted, quotes doubled.
std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
    std::string quoted = "\"";
    for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

std::string csvLine(const std::vector<std::string>& fields) {
    std::string line;
    for (const std::string& field : fields) {
        if (!line.empty()) line += ',';
        line += csvField(field);
    }
    return line + "\n";
}

// Every stat name any row reports, in the order first seen.
std::vector<std::string> statNames(const SweepResults& results) {
    std::vector<std::string> names;
    for (const SweepRow& row : results.rows)
        for (const TechniqueStat& s : row.stats)
            if (std::ranges::find(names, s.name) == names.end()) names.push_back(s.name);
    return names;
}

std::string statValue(const SweepRow& row, const std::string& name) {
    const auto stat = std::ranges::find(row.stats, name, &TechniqueStat::name);
    return stat == row.stats.end() ? "" : number(stat->value);
}

}  // namespace

SweepAxis parseSweepAxis(const std::string& text) {
    std::map<std::string, std::string> assignment;
    parseParamAssignment(text, assignment);
    SweepAxis axis{assignment.begin()->first, {}};
    std::istringstream values(assignment.begin()->second + ",");
    for (std::string value; std::getline(values, value, ',');) {
        if (value.empty()) throw std::invalid_argument("--param " + text + ": empty value in the comma-separated list");
        axis.values.push_back(value);
    }
    return axis;
}

std::string SweepRow::settingsLabel() const {
    std::string label;
    for (const auto& [name, value] : settings) label += (label.empty() ? "" : " ") + name + "=" + value;
    return label.empty() ? "defaults" : label;
}

SweepResults runSweep(const SweepOptions& options) {
    if (options.techniques.empty()) throw std::invalid_argument("sweep: give at least one technique");
    if (options.runs < 1 || options.warmupRuns < 0) throw std::invalid_argument("sweep: runs must be >= 1, warm-up runs >= 0");
    const std::vector<SweepPlan> plans = planSweep(options);
    const std::vector<int> threads = threadCounts(options);
    const Scene scene = loadScene(options.scene);
    const WorldGeometry world = flatten(scene);
    // One frame per setting first: a value the technique rejects fails before the long part.
    for (const SweepPlan& plan : plans)
        for (const Settings& settings : plan.settings) renderFrame(scene, world, *plan.technique, {options.simd, settings, {}});
    const ImageChannels reference = renderReferenceVisibility(scene, world, options.simd);
    SweepResults results{scene.name, {}, {}};
    for (const SweepPlan& plan : plans) results.techniques.push_back(plan.technique->name);
    for (const SweepPlan& plan : plans) {
        for (const Settings& settings : plan.settings) {
            for (int n : threads) {
                const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(n));
                SweepRow row = measure(scene, world, reference, *plan.technique, {options.simd, settings, {}}, options);
                row.threads = n;
                results.rows.push_back(std::move(row));
            }
        }
    }
    return results;
}

std::string sweepFileStem(const SweepResults& results) {
    std::string techniques;
    for (const std::string& technique : results.techniques) techniques += (techniques.empty() ? "" : "+") + technique;
    return results.scene + "-" + techniques;
}

std::string formatSweepText(const SweepResults& results) {
    std::string text = results.scene + "\n";
    char line[512];
    std::snprintf(line, sizeof line, "%-16s %-40s %7s %10s %10s %14s %10s\n", "technique", "settings", "threads",
                  "median ms", "min ms", "misclassified%", "RMS");
    text += line;
    for (const SweepRow& r : results.rows) {
        std::snprintf(line, sizeof line, "%-16s %-40s %7d %10.3f %10.3f %14.4f %10.5f\n", r.technique.c_str(),
                      r.settingsLabel().c_str(), r.threads, r.medianMs, r.minMs,
                      r.errors.percentOfPixels(r.errors.misclassified()), r.errors.rms);
        text += line;
    }
    return text;
}

std::string formatSweepCsv(const SweepResults& results) {
    const std::vector<std::string> stats = statNames(results);
    std::vector<std::string> header = {"technique", "settings", "threads", "median_ms", "min_ms", "rms", "mean_abs",
                                       "max_abs", "misclassified_percent", "false_shadow_percent", "false_light_percent"};
    header.insert(header.end(), stats.begin(), stats.end());
    std::string csv = csvLine(header);
    for (const SweepRow& r : results.rows) {
        const ErrorFigures& e = r.errors;
        std::vector<std::string> fields = {r.technique, r.settingsLabel(), std::to_string(r.threads),
                                           number(r.medianMs), number(r.minMs), number(e.rms), number(e.meanAbs),
                                           number(e.maxAbs), number(e.percentOfPixels(e.misclassified())),
                                           number(e.percentOfPixels(e.falseShadow)), number(e.percentOfPixels(e.falseLight))};
        for (const std::string& name : stats) fields.push_back(statValue(r, name));
        csv += csvLine(fields);
    }
    return csv;
}

std::string formatSweepJson(const SweepResults& results) {
    nlohmann::ordered_json rows = nlohmann::ordered_json::array();
    for (const SweepRow& r : results.rows) {
        nlohmann::ordered_json stats = nlohmann::ordered_json::object();
        for (const TechniqueStat& s : r.stats) stats[s.name] = s.value;
        rows.push_back({{"technique", r.technique},
                        {"settings", r.settings},
                        {"threads", r.threads},
                        {"median_ms", r.medianMs},
                        {"min_ms", r.minMs},
                        {"errors", nlohmann::ordered_json::parse(formatJson(r.errors))},
                        {"stats", stats}});
    }
    nlohmann::ordered_json j;
    j["scene"] = results.scene;
    j["rows"] = rows;
    return j.dump(2) + "\n";
}

}  // namespace shadowlab
