// env-subtractive: subtractive shadows (DeCoro and Rusinkiewicz 2008, section 2). The five
// steps, in the paper's order:
//   1. sample the environment into N shadow-casting lights (environment_lights.h: median
//      cut, or the paper's structured importance sampling);
//   2. for each light, find where it is occluded and accumulate its contribution there
//      into the shadow buffer S, at the sampling detail's resolution (light_passes.h,
//      LightPart::Occluded; sampling_detail.h);
//   3. the unshadowed direct light C by fast local illumination (unshadowed_light.h: SH
//      irradiance and prefiltered lobes, or the radiance cache of section 3.1);
//   4. S resampled to full size, S' (bilateral_upsample.h);
//   5. C - S', clamped at 0: the lights' contributions sum to the map's integral only
//      approximately, so where every light is occluded S' may exceed C by the sampling's
//      error (counted as `clamped_pixels`). The scene's own lights are added on top.
#include <algorithm>

#include "shadows/camera_pass.h"
#include "shadows/environment/bilateral_upsample.h"
#include "shadows/environment/environment_source.h"
#include "shadows/environment/environment_techniques.h"
#include "shadows/environment/light_passes.h"
#include "shadows/environment/sampling_detail.h"
#include "shadows/environment/subtractive_debug.h"
#include "shadows/environment/unshadowed_light.h"
#include "shadows/stage_timer.h"

namespace shadowlab {
namespace {

// The receivers at a lower sampling detail, lifted as the frame lifted the whole G-buffer
// against simplified casters (ShadowInputs::receiverLiftM).
GBuffer sampledReceivers(const ShadowInputs& in, const Camera& camera) {
    GBuffer g = renderGBuffer(in.receiverWorld(), camera, in.simd);
    return in.receiverLiftM.empty() ? g : liftedReceivers(std::move(g), in.receiverWorld(), in.receiverLiftM);
}

// Step 5: max(0, C - S'); returns the pixels where a channel was clamped.
uint64_t subtract(const std::vector<glm::vec3>& C, const std::vector<glm::vec3>& shadow, std::vector<glm::vec3>& out) {
    uint64_t clamped = 0;
    for (size_t k = 0; k < C.size(); ++k) {
        const glm::vec3 difference = C[k] - shadow[k];
        out[k] += glm::max(difference, glm::vec3(0.0f));
        clamped += difference.r < 0.0f || difference.g < 0.0f || difference.b < 0.0f;
    }
    return clamped;
}

struct SubtractiveSettings {
    SampledLightSettings lights;
    int samplingDetail = 1;   // k: S at 1/k^2 of the pixels
    UnshadowedSettings unshadowed;
};

const SettingsTable<SubtractiveSettings>& subtractiveSettingsTable() {
    using S = SubtractiveSettings;
    static const auto table = SettingsTable<S>()
                                  .include(member(&S::lights), sampledLightSettingsTable())
                                  .choice("sampling-detail", member(&S::samplingDetail), samplingDetailChoices(),
                                          "share of the pixels the shadow buffer S is computed at")
                                  .include(member(&S::unshadowed), unshadowedSettingsTable());
    return table;
}

std::vector<TechniqueStat> prepareSubtractive(const PreparedScene& prepared, const PreparedScene& casters,
                                              const TechniqueParams& params) {
    const SubtractiveSettings settings = subtractiveSettingsTable().read(params);
    std::vector<TechniqueStat> stats = prepareSampledLights(prepared, casters, settings.lights);
    for (TechniqueStat& s : prepareUnshadowedLight(prepared, settings.unshadowed)) stats.push_back(std::move(s));
    return stats;
}

ShadowOutputs runSubtractive(const ShadowInputs& in) {
    const SubtractiveSettings settings = subtractiveSettingsTable().read(in.params);
    refuseUnservedMaterials(in, settings.unshadowed);
    StageTimer timer;
    const EnvironmentMap& map = sceneEnvironment(in.prepared);
    std::vector<uint32_t> regions;
    const std::vector<EnvironmentLight> lights =
        sampleLights(in.prepared, settings.lights.sampling, in.debugDir.empty() ? nullptr : &regions);
    const LightLobes lobes = settings.lights.lobes;
    timer.lap("sampling");

    const int k = settings.samplingDetail;
    const Camera camera = sampledCamera(in.camera(), k);
    const GBuffer sampledGBuffer = k == 1 ? GBuffer{} : sampledReceivers(in, camera);
    const GBuffer& sampled = k == 1 ? in.gbuffer : sampledGBuffer;
    timer.lap("sampled_gbuffer");
    LightVisibility visibility(in, settings.lights.visibility);
    std::vector<glm::vec3> S(sampled.pixelCount(), glm::vec3(0.0f));
    const uint64_t fragments = addSampledLights(in, visibility, lights, lobes, sampled, camera, LightPart::Occluded, S, timer);

    std::vector<TechniqueStat> cStats;
    const std::vector<glm::vec3> C = unshadowedLight(in, settings.unshadowed, cStats);
    timer.lap("unshadowed_light");
    UpsampleCounts counts;
    const std::vector<glm::vec3> resampled = upsampleShadowBuffer(in.gbuffer, in.camera(), sampled, S, &counts);
    timer.lap("resample");
    ShadowOutputs out;
    out.radiance.assign(in.gbuffer.pixelCount(), glm::vec3(0.0f));
    const uint64_t clamped = subtract(C, resampled, out.radiance);
    addSceneLights(in, visibility, out.radiance);
    timer.lap("composite");

    const uint64_t sampledPixels = uint64_t(std::count(sampled.hit.begin(), sampled.hit.end(), uint8_t(1)));
    out.stats = {{"lights_count", double(lights.size())},
                 {"sampled_pixels", double(sampledPixels)},
                 {"shadow_fragments", double(fragments)},
                 {"clamped_pixels", double(clamped)},
                 {"resample_nearest_pixels", double(counts.nearestPixels)},
                 {"resample_empty_pixels", double(counts.emptyPixels)}};
    out.stats.insert(out.stats.end(), cStats.begin(), cStats.end());
    timer.appendTo(out.stats);
    visibility.appendStatsTo(out.stats);
    writeSubtractiveDebug({in.debugDir, "env-subtractive"}, in, map, {lights, regions}, {C, S, sampled, resampled});
    return out;
}

}  // namespace

Technique environmentSubtractiveTechnique() {
    return {.name = "env-subtractive",
            .description = "environment light, subtractive shadows (DeCoro and Rusinkiewicz 2008): fast local "
                           "illumination C less the occluded light of N lights, S, at a sampling detail",
            .params = subtractiveSettingsTable().specs(),
            .run = runSubtractive,
            .referenceName = "reference-env",
            .output = TechniqueOutput::Radiance,
            .prepare = prepareSubtractive};
}

}  // namespace shadowlab
