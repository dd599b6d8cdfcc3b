#include "app/sweep_json.h"

#include <array>

#include <nlohmann/json.hpp>

namespace shadowlab {
namespace {

using Json = nlohmann::ordered_json;

std::array<float, 3> xyz(const glm::vec3& v) { return {v.x, v.y, v.z}; }

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
    return {{"setting", r.setting},
            {"technique", r.technique},
            {"reference", r.reference},
            {"settings", r.settings},
            {"threads", r.threads},
            {"median_ms", r.medianMs},
            {"min_ms", r.minMs},
            {"errors", Json::parse(formatJson(r.errors))},
            {"stats", stats}};
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

}  // namespace shadowlab
