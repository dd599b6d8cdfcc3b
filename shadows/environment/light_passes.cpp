#include "shadows/environment/light_passes.h"

namespace shadowlab {

const SettingsTable<SampledLightSettings>& sampledLightSettingsTable() {
    using S = SampledLightSettings;
    static const auto table =
        SettingsTable<S>()
            .include(member(&S::sampling), lightSamplingSettingsTable())
            .choice("light-lobes", member(&S::lobes),
                    {{"point", LightLobes::Point, "each light a point, as the paper"},
                     {"region", LightLobes::Region, "each light's lobe widened by its region's solid angle (ours)"}},
                    "how a sampled light's specular highlight is shaded")
            .include(member(&S::visibility), lightVisibilitySettingsTable());
    return table;
}

std::vector<TechniqueStat> prepareSampledLights(const PreparedScene& prepared, const PreparedScene& casters,
                                                const SampledLightSettings& settings) {
    std::vector<TechniqueStat> stats = prepareLightSampling(prepared, settings.sampling);
    for (TechniqueStat& s : prepareLightVisibility(casters, settings.visibility)) stats.push_back(std::move(s));
    return stats;
}

uint64_t addSampledLights(const ShadowInputs& in, LightVisibility& visibility, const std::vector<EnvironmentLight>& lights,
                          LightLobes lobes, const GBuffer& g, const Camera& camera, LightPart part,
                          std::vector<glm::vec3>& sum, StageTimer& timer) {
    uint64_t shaded = 0;
    for (const EnvironmentLight& environmentLight : lights) {
        const Light light = directionalLight(environmentLight);
        const std::vector<float> V = visibility.of(light, g, camera);
        timer.lap("visibility");
        shaded += addDistantLight(g, lightMaterials(in.scene(), environmentLight, lobes), in.scene().albedoTextures, camera.eye, light.direction,
                                  light.intensity, V, part, sum);
        timer.lap(part == LightPart::Lit ? "shading" : "shadow_buffer");
    }
    return shaded;
}

uint64_t addSceneLights(const ShadowInputs& in, LightVisibility& visibility, std::vector<glm::vec3>& radiance) {
    uint64_t shaded = 0;
    for (const Light& light : in.scene().lights) {
        const std::vector<float> V = visibility.of(light, in.gbuffer, in.camera());
        shaded += addSceneLight(in.gbuffer, in.scene().materials, in.scene().albedoTextures, in.camera().eye, light, V, LightPart::Lit, radiance);
    }
    return shaded;
}

}  // namespace shadowlab
