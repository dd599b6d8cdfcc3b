// env-additive and reference-env-lights: the additive sum over sampled lights (DeCoro and
// Rusinkiewicz 2008, section 1, "additive" shadowing), sum_l f E_l max(0, Ns . w_l) V_l.
#include "compositing/environment_lights.h"
#include "compositing/environment_source.h"
#include "compositing/environment_techniques.h"
#include "compositing/light_passes.h"
#include "shadows/stage_timer.h"

namespace shadowlab {
namespace {

ShadowOutputs runAdditive(const ShadowInputs& in) {
    StageTimer timer;
    const std::vector<EnvironmentLight> lights = sampleLights(in.prepared, in.params);
    const LightLobes lobes = in.params.choice<LightLobes>("light-lobes");
    timer.lap("sampling");
    LightVisibility visibility(in);
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

Technique additive(std::string name, std::string description, int lights, const char* visibility) {
    std::vector<ParamSpec> params = {environmentLightsParam(lights), lightSamplerParam(), lightLobesParam()};
    for (ParamSpec& p : visibilityParams(visibility)) params.push_back(std::move(p));
    return {.name = std::move(name),
            .description = std::move(description),
            .params = std::move(params),
            .run = runAdditive,
            .referenceName = "reference-env",
            .output = TechniqueOutput::Radiance,
            .prepare = prepareSampledLights};
}

}  // namespace

Technique environmentAdditiveTechnique() {
    return additive("env-additive",
                    "environment light, additive: N lights sampled from the map, each shaded where it is visible", 40,
                    "shadow-map");
}

Technique environmentLightsReferenceTechnique() {
    return additive("reference-env-lights",
                    "environment light by 1000 lights sampled from the map, with exact visibility (the paper's reference)", 1000,
                    "exact");
}

}  // namespace shadowlab
