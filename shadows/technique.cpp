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

std::vector<TechniqueStat> prepareEdgeAdjacency(const PreparedScene& prepared, const TechniqueParams&) {
    if (const std::optional<double> ms = prepared.buildEdgeAdjacency()) return {{"edge_adjacency_ms", *ms}};
    return {};
}

Light pointLightFor(const Light& light) {
    if (light.type != LightType::Disk && light.type != LightType::Rectangle) return light;
    Light point = light;
    point.type = LightType::Point;
    return point;
}

}  // namespace shadowlab
