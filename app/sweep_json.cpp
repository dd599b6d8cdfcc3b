#include "app/sweep_json.h"

#include <array>
#include <limits>
#include <optional>
#include <stdexcept>
#include <variant>

#include <nlohmann/json.hpp>

#include "scenes/scene_limits.h"

namespace shadowlab {
namespace {

// Ordered: a row's stats keep the order the technique reported them in, which is the
// order of the CSV's columns.
using Json = nlohmann::ordered_json;

// Only the overrides given, so that a sweep without any writes {}.
Json overridesJson(const SceneOverrides& o) {
    Json j = Json::object();
    if (o.width) j["width"] = *o.width;
    if (o.height) j["height"] = *o.height;
    if (o.eye) j["eye"] = xyz(*o.eye);
    if (o.target) j["target"] = xyz(*o.target);
    if (o.fovyDeg) j["fovy"] = *o.fovyDeg;
    if (o.lightPosition) j["light_position"] = xyz(*o.lightPosition);
    if (o.lightRadius) j["light_radius"] = *o.lightRadius;
    return j;
}

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

template <class T>
void readOptional(const Json& j, const char* key, std::optional<T>& into) {
    if (j.contains(key)) into = j.at(key).get<T>();
}

void readOptional(const Json& j, const char* key, std::optional<glm::vec3>& into) {
    if (!j.contains(key)) return;
    const auto v = j.at(key).get<std::array<float, 3>>();
    into = glm::vec3(v[0], v[1], v[2]);
}

SceneOverrides readOverrides(const Json& j) {
    SceneOverrides o;
    readOptional(j, "width", o.width);
    readOptional(j, "height", o.height);
    readOptional(j, "eye", o.eye);
    readOptional(j, "target", o.target);
    readOptional(j, "fovy", o.fovyDeg);
    readOptional(j, "light_position", o.lightPosition);
    readOptional(j, "light_radius", o.lightRadius);
    return o;
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
    e.fullUmbraPixels = j.at("full_umbra_pixels").get<uint64_t>();
    e.fullUmbraLit = j.at("full_umbra_lit").get<uint64_t>();
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

// The fields a sweep's row and a render's JSON share: what was run, against what, how
// well, its stats and its pictures.
SweepRow readScoredRow(const Json& j) {
    SweepRow r;
    r.technique = j.at("technique").get<std::string>();
    r.reference = j.at("reference").get<std::string>();
    r.settings = j.at("settings").get<std::map<std::string, std::string>>();
    r.errors = readErrors(j.at("errors"));
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
        ScoreRecord record{j.at("scene").get<std::string>(), readScoredRow(j)};
        record.row.threads = 0;
        record.row.medianMs = record.row.minMs = number(j.at("technique_ms"));
        return record;
    } catch (const Json::exception& error) {
        throw std::runtime_error(std::string("not the JSON of render --error-map --json: ") + error.what());
    }
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
    } catch (const Json::exception& error) {
        throw std::runtime_error("not the JSON of a sweep: " + where + error.what());
    }
    if (!r.shard.valid())
        throw std::runtime_error("shard " + r.shard.name() + ": not a shard (1 <= index <= count)");
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
