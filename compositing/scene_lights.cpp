#include "compositing/scene_lights.h"

#include "compositing/light_contribution.h"

namespace shadowlab {

uint64_t addSceneLights(const ShadowInputs& in, LightVisibility& visibility, std::vector<glm::vec3>& radiance) {
    uint64_t shaded = 0;
    for (const Light& light : in.scene().lights) {
        const std::vector<float> V = visibility.of(light, in.gbuffer, in.camera());
        shaded += addSceneLight(in.gbuffer, in.scene().materials, in.camera().eye, light, V, LightPart::Lit, radiance);
    }
    return shaded;
}

}  // namespace shadowlab
