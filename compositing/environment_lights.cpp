#include "compositing/environment_lights.h"

namespace shadowlab {

ParamSpec environmentLightsParam(int defaultCount) {
    return integerParam("lights", defaultCount, 1, 4096,
                        "N, the lights sampled from the environment by median cut (illumination detail)");
}

Light directionalLight(const EnvironmentLight& light) {
    return {.type = LightType::Directional, .direction = glm::vec3(light.direction), .intensity = glm::vec3(light.power)};
}

}  // namespace shadowlab
