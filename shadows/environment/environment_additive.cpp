// env-additive and reference-env-lights: the additive sum over sampled lights (DeCoro and
// Rusinkiewicz 2008, section 1, "additive" shadowing), sum_l f E_l max(0, Ns . w_l) V_l.
#include "shadows/environment/environment_techniques.h"
#include "shadows/environment/light_passes.h"
#include "shadows/stage_timer.h"

namespace shadowlab {
namespace {

ShadowOutputs runAdditive(const ShadowInputs& in) {
    const SampledLightSettings settings = sampledLightSettingsTable().read(in.params);
    StageTimer timer;
    const std::vector<EnvironmentLight> lights = sampleLights(in.prepared, settings.sampling);
    const LightLobes lobes = settings.lobes;
    timer.lap("sampling");
    LightVisibility visibility(in, settings.visibility);
    const GBuffer& g = in.gbuffer;
    ShadowOutputs out;
    out.radiance.assign(g.pixelCount(), glm::vec3(0.0f));
    uint64_t fragments = addSampledLights(in, visibility, lights, lobes, g, in.camera(), LightPart::Lit, out.radiance, timer);
    fragments += addSceneLights(in, visibility, out.radiance);
    timer.lap("scene_lights");
    out.stats = {{"lights_count", double(lights.size())}, {"shaded_fragments", double(fragments)}};
    timer.appendTo(out.stats);
    visibility.appendStatsTo(out.stats);
    return out;
}

Technique additive(std::string name, std::string description, const SampledLightSettings& defaults) {
    return {.name = std::move(name),
            .description = std::move(description),
            .params = sampledLightSettingsTable().specs(defaults),
            .run = runAdditive,
            .referenceName = "reference-env",
            .output = TechniqueOutput::Radiance,
            .prepare = [](const PreparedScene& prepared, const PreparedScene& casters, const TechniqueParams& params) {
                return prepareSampledLights(prepared, casters, sampledLightSettingsTable().read(params));
            }};
}

}  // namespace

Technique environmentAdditiveTechnique() {
    return additive("env-additive",
                    "environment light, additive: N lights sampled from the map, each shaded where it is visible",
                    {.sampling = {.count = 40}, .visibility = {.method = VisibilityMethod::ShadowMap}});
}

Technique environmentLightsReferenceTechnique() {
    return additive("reference-env-lights",
                    "environment light by 1000 lights sampled from the map, with exact visibility (the paper's reference)",
                    {.sampling = {.count = 1000}, .visibility = {.method = VisibilityMethod::Exact}});
}

}  // namespace shadowlab
