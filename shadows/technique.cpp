#include "shadows/technique.h"

#include <algorithm>

namespace shadowlab {

bool anySurface(const GBuffer& g) { return std::find(g.hit.begin(), g.hit.end(), 1) != g.hit.end(); }

ShadowOutputs unlitOutputs(const GBuffer& g) {
    ShadowOutputs out;
    out.visibility.assign(g.pixelCount(), 0.0f);
    return out;
}

Light pointLightFor(const Light& light) {
    if (light.type != LightType::Disk && light.type != LightType::Rectangle) return light;
    Light point = light;
    point.type = LightType::Point;
    return point;
}

}  // namespace shadowlab
