#include "app/measure/sweep_json.h"

#include <algorithm>
#include <array>
#include <limits>
#include <optional>
#include <stdexcept>
#include <variant>

#include <nlohmann/json.hpp>

#include "raster/thread_count.h"
#include "scenes/scene_limits.h"

namespace shadowlab {
namespace {

// Ordered: a row's stats keep the order the technique reported them in, which is the
// order of the CSV's columns.
using Json = nlohmann::ordered_json;

Json gridJson(const SweepResults& results) {
    const SweepGrid& g = results.grid;
    Json axes = Json::array();
    for (const SweepAxis& axis : g.axes) axes.push_back({{"name", axis.name}, {"values", axis.values}});
    Json fingerprints = Json::object();
    for (const auto& [name, hex] : g.referenceFingerprints) fingerprints[name] = hex;
    return {{"techniques", results.techniques}, {"axes", axes}, {"overrides", overridesJson(g.overrides)},
            {"reference", g.reference}, {"reference_fingerprints", fingerprints}, {"threads", g.threads},
            {"warmup", g.warmupRuns}, {"runs", g.runs}, {"settings", g.settings}};
}

// [{"light": K, "errors": formatJson(...)}], the fields of render --json's "lights" that a
// sweep's row has (each light's time is its stat lightK_technique_ms).
Json lightsJson(const std::vector<ErrorFigures>& lightErrors) {
    Json lights = Json::array();
    for (size_t k = 0; k < lightErrors.size(); ++k)
        lights.push_back({{"light", k}, {"errors", Json::parse(formatJson(lightErrors[k]))}});
    return lights;
}

Json rowJson(const SweepRow& r) {
    Json stats = Json::object();
    for (const TechniqueStat& s : r.stats) stats[s.name] = s.value;
    Json j = {{"setting", r.setting},
              {"technique", r.technique},
              {"reference", r.reference},
              {"settings", r.settings},
              {"threads", r.threads},
              {"median_ms", r.medianMs},
              {"min_ms", r.minMs},
              {"errors", Json::parse(formatJson(r.errors))},
              {"stats", stats}};
    // Only for several lights: a sweep of one light writes the JSON it always did.
    if (!r.lightErrors.empty()) j["lights"] = lightsJson(r.lightErrors);
    // Only with pictures (sweep --images): the JSON of a sweep without them stays as it was.
    if (!r.images.empty()) j["images"] = Json::parse(formatFrameImagesJson(r.images));
    return j;
}

// A sweep's JSON is 5 levels deep; a deeper file would only strain the recursive parser.
Json parseOrderedJson(const std::string& text) {
    try {
        return Json::parse(text, [](int depth, Json::parse_event_t, Json&) {
            if (depth > kMaxJsonDepth) throw std::runtime_error("nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
            return true;
        });
    } catch (const Json::exception& error) {
        throw std::runtime_error(std::string("invalid JSON: ") + error.what());
    }
}

// formatSweepJson writes NaN as null.
double number(const Json& value) {
    return value.is_null() ? std::numeric_limits<double>::quiet_NaN() : value.get<double>();
}

SweepGrid readGrid(const Json& j) {
    SweepGrid g;
    for (const Json& axis : j.at("axes"))
        g.axes.push_back({axis.at("name").get<std::string>(), axis.at("values").get<std::vector<std::string>>()});
    g.overrides = readOverrides(j.at("overrides"));
    g.reference = j.at("reference").get<std::string>();
    g.referenceFingerprints = j.at("reference_fingerprints").get<std::map<std::string, std::string>>();
    g.threads = j.at("threads").get<std::vector<int>>();
    g.warmupRuns = j.at("warmup").get<int>();
    g.runs = j.at("runs").get<int>();
    g.settings = j.at("settings").get<uint64_t>();
    return g;
}

// The raw counts of formatJson(ErrorFigures); the percentages follow from them.
ErrorFigures readErrors(const Json& j) {
    ErrorFigures e;
    e.channel = j.at("channel").get<std::string>();
    e.pixels = j.at("pixels").get<uint64_t>();
    e.rms = number(j.at("rms"));
    if (j.contains("rms_display")) e.rmsDisplay = number(j.at("rms_display"));
    if (j.contains("flip_mean")) e.flipMean = number(j.at("flip_mean"));   // absent before FLIP was scored
    e.meanAbs = number(j.at("mean_abs"));
    e.maxAbs = number(j.at("max_abs"));
    e.binary = j.at("binary").get<bool>();
    e.falseShadow = j.at("false_shadow").get<uint64_t>();
    e.falseLight = j.at("false_light").get<uint64_t>();
    e.umbraPixels = j.at("umbra_pixels").get<uint64_t>();
    e.litPixels = j.at("lit_pixels").get<uint64_t>();
    e.umbraLit = j.at("umbra_lit").get<uint64_t>();
    e.umbraOver = j.at("umbra_over").get<uint64_t>();
    e.litShadowed = j.at("lit_shadowed").get<uint64_t>();
    // Older JSON has no full umbra: read it as not recorded, not as zero.
    e.fullUmbraRecorded = j.contains("full_umbra_pixels") || j.contains("full_umbra_lit");
    if (e.fullUmbraRecorded) {
        e.fullUmbraPixels = j.at("full_umbra_pixels").get<uint64_t>();
        e.fullUmbraLit = j.at("full_umbra_lit").get<uint64_t>();
    }
    return e;
}

std::string readOptionalPath(const Json& j, const char* key) {
    return j.contains(key) ? j.at(key).get<std::string>() : std::string();
}

FrameImages readImages(const Json& j) {
    FrameImages images;
    images.image = readOptionalPath(j, "image");
    images.errorMap = readOptionalPath(j, "error_map");
    images.visibility = readOptionalPath(j, "visibility");
    images.referenceImage = readOptionalPath(j, "reference_image");
    images.referenceVisibility = readOptionalPath(j, "reference_visibility");
    if (j.contains("debug_buffers")) images.debugBuffers = j.at("debug_buffers").get<std::vector<std::string>>();
    return images;
}

// Each light's figures, lights 0, 1, ... in order; a file written before they were has
// none. One light alone is not written (its figures are the row's).
std::vector<ErrorFigures> readLightErrors(const Json& j) {
    std::vector<ErrorFigures> lightErrors;
    if (!j.contains("lights")) return lightErrors;
    const Json& lights = j.at("lights");
    if (!lights.is_array() || lights.size() < 2 || lights.size() > kMaxSceneLights)
        throw std::runtime_error("lights: expected an array of 2.." + std::to_string(kMaxSceneLights) + " lights");
    for (const Json& light : lights) {
        if (light.at("light").get<uint64_t>() != lightErrors.size())
            throw std::runtime_error("lights[" + std::to_string(lightErrors.size()) + "].light is " +
                                     light.at("light").dump() + ", expected " + std::to_string(lightErrors.size()));
        lightErrors.push_back(readErrors(light.at("errors")));
    }
    return lightErrors;
}

// The fields a sweep's row and a render's JSON share: what was run, against what, how
// well (over every light, and each light's), its stats and its pictures.
SweepRow readScoredRow(const Json& j) {
    SweepRow r;
    r.technique = j.at("technique").get<std::string>();
    r.reference = j.at("reference").get<std::string>();
    r.settings = j.at("settings").get<std::map<std::string, std::string>>();
    r.errors = readErrors(j.at("errors"));
    r.lightErrors = readLightErrors(j);
    for (const auto& [name, value] : j.at("stats").items()) r.stats.push_back({name, number(value)});
    if (j.contains("images")) r.images = readImages(j.at("images"));
    return r;
}

SweepRow readRow(const Json& j) {
    SweepRow r = readScoredRow(j);
    r.setting = j.at("setting").get<uint64_t>();
    r.threads = j.at("threads").get<int>();
    r.medianMs = number(j.at("median_ms"));
    r.minMs = number(j.at("min_ms"));
    return r;
}

// A render's one frame: technique_ms is its median and minimum; threads 0 (not recorded).
ScoreRecord readScore(const Json& j) {
    try {
        ScoreRecord record{j.at("scene").get<std::string>(), readScoredRow(j), {}};
        if (j.contains("overrides")) record.overrides = readOverrides(j.at("overrides"));
        record.row.threads = 0;
        record.row.medianMs = record.row.minMs = number(j.at("technique_ms"));
        return record;
    } catch (const std::exception& error) {   // a Json::exception, or readLightErrors'
        throw std::runtime_error(std::string("not the JSON of render --error-map --json: ") + error.what());
    }
}

// Every count the file carries, checked before any is used to size or bound a loop (a
// shard of 1/1000000000, a grid of 2^63 settings or no thread counts kept merge-sweep busy
// for ever): the shard within the grid, thread counts as `sweep --threads` takes them,
// runs as `--runs` and `--warmup` do, and exactly the rows the shard's settings make.
void checkCounts(const SweepResults& r) {
    const SweepGrid& g = r.grid;
    const auto fail = [](const std::string& problem) { throw std::runtime_error("not the JSON of a sweep: " + problem); };
    if (!r.shard.valid()) fail("shard " + r.shard.name() + ": not a shard (1 <= index <= count)");
    if (g.settings < 1 || uint64_t(r.shard.count) > g.settings)
        fail("grid.settings " + std::to_string(g.settings) + " must be at least 1 and the shards' count " +
             std::to_string(r.shard.count));
    if (g.threads.empty()) fail("grid.threads lists no thread count");
    if (const std::optional<int> n = badThreadCount(g.threads))
        fail("grid.threads: each must be 1.." + std::to_string(kMaxThreads) + " and given once, got " + std::to_string(*n));
    if (!runsInRange(g.runs, g.warmupRuns))
        fail("grid.runs must be 1.." + std::to_string(kMaxRuns) + " and grid.warmup 0.." + std::to_string(kMaxWarmupRuns));
    const uint64_t held = r.shard.heldOf(g.settings);
    if (held > r.rows.size() || held * g.threads.size() != r.rows.size())
        fail("shard " + r.shard.name() + " of " + std::to_string(g.settings) + " settings at " + std::to_string(g.threads.size()) +
             " thread counts has " + std::to_string(held) + " x " + std::to_string(g.threads.size()) + " rows, the file " +
             std::to_string(r.rows.size()));
}

SweepResults readSweep(const Json& j) {
    SweepResults r;
    std::string where;   // the row being read, for the message
    try {
        r.scene = j.at("scene").get<std::string>();
        r.techniques = j.at("grid").at("techniques").get<std::vector<std::string>>();
        r.grid = readGrid(j.at("grid"));
        r.shard = {j.at("shard").at("index").get<int>(), j.at("shard").at("count").get<int>()};
        for (const Json& row : j.at("rows")) {
            where = "rows[" + std::to_string(r.rows.size()) + "]: ";
            r.rows.push_back(readRow(row));
        }
    } catch (const std::exception& error) {   // a Json::exception, or readLightErrors'
        throw std::runtime_error("not the JSON of a sweep: " + where + error.what());
    }
    checkCounts(r);
    return r;
}

// The fields two parts of one sweep share, in the order formatSweepJson writes them.
Json identity(const SweepResults& results) {
    Json j = {{"scene", results.scene}};
    j.update(gridJson(results));
    return j;
}

std::string excerpt(const Json& value) {
    const std::string text = value.dump();
    constexpr size_t kMaxChars = 60;
    return text.size() <= kMaxChars ? text : text.substr(0, kMaxChars) + "...";
}

}  // namespace

std::string formatSweepJson(const SweepResults& results) {
    Json rows = Json::array();
    for (const SweepRow& r : results.rows) rows.push_back(rowJson(r));
    Json j;
    j["scene"] = results.scene;
    j["grid"] = gridJson(results);
    j["shard"] = {{"index", results.shard.index}, {"count", results.shard.count}};
    j["rows"] = rows;
    return j.dump(2) + "\n";
}

SweepResults parseSweepJson(const std::string& text, const std::string& file) {
    try {
        return readSweep(parseOrderedJson(text));
    } catch (const std::runtime_error& error) {
        throw std::runtime_error(file + ": " + error.what());
    }
}

std::variant<SweepResults, ScoreRecord> parseResultsJson(const std::string& text, const std::string& file) {
    try {
        const Json j = parseOrderedJson(text);
        if (j.is_object() && j.contains("grid") && j.contains("rows")) return readSweep(j);
        if (j.is_object() && j.contains("technique_ms") && j.contains("errors")) return readScore(j);
        throw std::runtime_error("neither a sweep's JSON (with grid and rows) nor that of render --error-map --json "
                                 "(with technique_ms and errors)");
    } catch (const std::runtime_error& error) {
        throw std::runtime_error(file + ": " + error.what());
    }
}

std::string sweepDifference(const SweepResults& a, const SweepResults& b) {
    const Json ja = identity(a), jb = identity(b);
    for (const auto& [key, value] : ja.items())
        if (jb.at(key) != value) return key + ": " + excerpt(value) + " against " + excerpt(jb.at(key));
    return "";
}

}  // namespace shadowlab
