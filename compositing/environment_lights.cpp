#include "compositing/environment_lights.h"

#include "compositing/environment_source.h"
#include "shading/environment/structured_sampling.h"

namespace shadowlab {

ParamSpec environmentLightsParam(int defaultCount) {
    return integerParam("lights", defaultCount, 1, 4096, "N, the lights sampled from the environment (illumination detail)");
}

ParamSpec lightSamplerParam() {
    return choiceParam<LightSampler>(
        "sampler", "median-cut",
        {{"median-cut", LightSampler::MedianCut, "regions of equal energy (Debevec 2005)"},
         {"structured", LightSampler::Structured, "structured importance sampling (Agarwal et al. 2003, the paper's)"}},
        "how the environment is sampled into lights");
}

std::vector<EnvironmentLight> sampleLights(const PreparedScene& prepared, const TechniqueParams& params,
                                           std::vector<uint32_t>* regionOfTexel) {
    const EnvironmentMap& map = sceneEnvironment(prepared);
    const int count = params.integer("lights");
    if (params.choice<LightSampler>("sampler") == LightSampler::Structured)
        return structuredLights(map, scenePyramid(prepared), count, regionOfTexel);
    std::vector<EnvironmentLight> lights = medianCutLights(map, count);
    if (regionOfTexel) *regionOfTexel = medianCutRegions(map, lights);
    return lights;
}

Light directionalLight(const EnvironmentLight& light) {
    return {.type = LightType::Directional, .direction = glm::vec3(light.direction), .intensity = glm::vec3(light.power)};
}

}  // namespace shadowlab
