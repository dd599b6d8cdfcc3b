#include "shadows/technique.h"

namespace shadowlab {

Light pointLightFor(const Light& light) {
    if (light.type != LightType::Disk && light.type != LightType::Rectangle) return light;
    Light point = light;
    point.type = LightType::Point;
    return point;
}

}  // namespace shadowlab
