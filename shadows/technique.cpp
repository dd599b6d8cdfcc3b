#include "shadows/technique.h"

#include <algorithm>
#include <optional>

namespace shadowlab {

bool anySurface(const GBuffer& g) { return std::find(g.hit.begin(), g.hit.end(), 1) != g.hit.end(); }

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
}

Technique withCasterLod(Technique technique) {
    technique.params.push_back(realParam(kCasterLod, 1.0, 0.001, 1.0,
                                         "share of the casters' triangles kept (meshoptimizer; receivers stay whole)"));
    return technique;
}

bool hasCasterLod(const Technique& technique) {
    return std::ranges::any_of(technique.params, [](const ParamSpec& p) { return p.name == kCasterLod; });
}

double casterLodRatio(const TechniqueParams& params) {
    return params.values().contains(kCasterLod) ? params.real(kCasterLod) : 1.0;
}

Light pointLightFor(const Light& light) {
    if (light.type != LightType::Disk && light.type != LightType::Rectangle) return light;
    Light point = light;
    point.type = LightType::Point;
    return point;
}

}  // namespace shadowlab
