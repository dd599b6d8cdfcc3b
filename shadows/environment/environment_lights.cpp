#include "shadows/environment/environment_lights.h"

#include "shading/environment/structured_sampling.h"
#include "shadows/environment/environment_source.h"

namespace shadowlab {

const SettingsTable<LightSamplingSettings>& lightSamplingSettingsTable() {
    using S = LightSamplingSettings;
    static const auto table =
        SettingsTable<S>()
            .integer("lights", member(&S::count), 1, 4096, "N, the lights sampled from the environment (illumination detail)")
            .choice("sampler", member(&S::sampler),
                    {{"median-cut", LightSampler::MedianCut, "regions of equal energy (Debevec 2005)"},
                     {"structured", LightSampler::Structured,
                      "structured importance sampling (Agarwal et al. 2003, the paper's)"}},
                    "how the environment is sampled into lights");
    return table;
}

std::vector<EnvironmentLight> sampleLights(const PreparedScene& prepared, const LightSamplingSettings& settings,
                                           std::vector<uint32_t>* regionOfTexel) {
    const EnvironmentMap& map = sceneEnvironment(prepared);
    if (settings.sampler == LightSampler::Structured)
        return structuredLights(map, scenePyramid(prepared), settings.count, regionOfTexel);
    std::vector<EnvironmentLight> lights = medianCutLights(map, settings.count);
    if (regionOfTexel) *regionOfTexel = medianCutRegions(map, lights);
    return lights;
}

std::vector<TechniqueStat> prepareLightSampling(const PreparedScene& prepared, const LightSamplingSettings& settings) {
    std::vector<TechniqueStat> stats = prepareEnvironment(prepared);
    if (settings.sampler == LightSampler::Structured) {
        std::optional<double> ms;
        scenePyramid(prepared, &ms);
        if (ms) stats.push_back({"environment_pyramid_ms", *ms});
    }
    return stats;
}

Light directionalLight(const EnvironmentLight& light) {
    return {.type = LightType::Directional, .direction = glm::vec3(light.direction), .intensity = glm::vec3(light.power)};
}

}  // namespace shadowlab
