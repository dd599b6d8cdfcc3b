#include "shadows/technique.h"

#include <algorithm>
#include <optional>

#include "shading/lights.h"
#include "shadows/settings_table.h"

namespace shadowlab {

bool anySurface(const GBuffer& g) { return std::find(g.hit.begin(), g.hit.end(), 1) != g.hit.end(); }

bool anyReachable(const GBuffer& g, const Light& light) {
    const LightReach reaches(light);
    for (size_t k = 0; k < g.pixelCount(); ++k) {
        if (g.hit[k] && reaches(g.position[k], g.normal[k])) return true;
    }
    return false;
}

ShadowOutputs unlitOutputs(const GBuffer& g) {
    ShadowOutputs out;
    out.visibility.assign(g.pixelCount(), 0.0f);
    return out;
}

std::vector<TechniqueStat> prepareCasterEdgeAdjacency(const PreparedScene& casters) {
    if (const std::optional<double> ms = casters.buildEdgeAdjacency()) return {{"edge_adjacency_ms", *ms}};
    return {};
}

std::vector<TechniqueStat> prepareEdgeAdjacency(const PreparedScene&, const PreparedScene& casters, const TechniqueParams&) {
    return prepareCasterEdgeAdjacency(casters);
}

namespace {

const char* const kCasterLod = "caster-lod";

struct CasterLodSettings {
    double ratio = 1.0;   // whole casters
};

const SettingsTable<CasterLodSettings>& casterLodSettingsTable() {
    static const auto table = SettingsTable<CasterLodSettings>().real(
        kCasterLod, member(&CasterLodSettings::ratio), 0.001, 1.0,
        "share of the casters' triangles kept (meshoptimizer; receivers stay whole)");
    return table;
}

}  // namespace

Technique withCasterLod(Technique technique) {
    for (const ParamSpec& spec : casterLodSettingsTable().specs()) technique.params.push_back(spec);
    return technique;
}

bool hasCasterLod(const Technique& technique) {
    return std::ranges::any_of(technique.params, [](const ParamSpec& p) { return p.name == kCasterLod; });
}

double casterLodRatio(const TechniqueParams& params) {
    return params.values().contains(kCasterLod) ? casterLodSettingsTable().read(params).ratio : 1.0;
}

Light pointLightFor(const Light& light) {
    Light point = light;
    if (light.type == LightType::Disk || light.type == LightType::Rectangle) point.type = LightType::Point;
    point.angularDiameterDeg = 0.0f;
    return point;
}

}  // namespace shadowlab
