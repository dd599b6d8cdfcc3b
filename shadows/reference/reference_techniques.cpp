#include "shadows/reference/reference_techniques.h"

#include <utility>

#include "shadows/reference/reference.h"
#include "shadows/reference/scene_rays.h"
#include "shadows/settings_table.h"
#include "shadows/stage_timer.h"

namespace shadowlab {
namespace {

ShadowOutputs unshadowed(const ShadowInputs& in) {
    ShadowOutputs out;
    out.visibility.resize(in.gbuffer.pixelCount());
    for (size_t k = 0; k < out.visibility.size(); ++k) out.visibility[k] = in.gbuffer.hit[k] ? 1.0f : 0.0f;
    return out;
}

// V of `light` by Embree rays through the scene's BVH, built by its first frame and kept
// (scene_rays.h): both stages timed, "bvh" near 0 once built.
ShadowOutputs referenceVisibility(const ShadowInputs& in, const Light& light, ReferenceOptions options) {
    StageTimer timer;
    const ReferenceVisibility& reference = sceneRays(in.casters());
    timer.lap("bvh");
    options.progress = in.progress;
    ShadowOutputs out;
    ReferenceVisibility::Passed passed = reference.passed(in.gbuffer, light, options);
    out.visibility = std::move(passed.visibility);
    out.colouredVisibility = std::move(passed.coloured);
    timer.lap("rays");
    timer.appendTo(out.stats);
    return out;
}

ShadowOutputs exactReference(const ShadowInputs& in) { return referenceVisibility(in, pointLightFor(in.light), {}); }

struct SoftReferenceSettings {
    int samplesPerAxis = 32;
};

const SettingsTable<SoftReferenceSettings>& softReferenceSettingsTable() {
    static const auto table = SettingsTable<SoftReferenceSettings>().integer(
        "samples-per-axis", member(&SoftReferenceSettings::samplesPerAxis), 1, 256, "n: n x n samples on the light");
    return table;
}

// The soft shadows' reference: the visible fraction of the area light itself, or of a sun's
// disk on the sky, from n x n stratified samples (reference.h); point lights and point-like
// suns give hard shadows.
ShadowOutputs exactSoftReference(const ShadowInputs& in) {
    const SoftReferenceSettings settings = softReferenceSettingsTable().read(in.params);
    return referenceVisibility(in, in.light, {.areaSamplesPerAxis = settings.samplesPerAxis});
}

}  // namespace

Technique unshadowedTechnique() {
    return {.name = "none",
            .description = "no shadows: V = 1 on every surface",
            .params = {},
            .run = unshadowed,
            .referenceName = "reference",
            .output = TechniqueOutput::Visibility};
}

Technique referenceTechnique() {
    return {.name = "reference",
            .description = "exact hard shadows: one Embree shadow ray per pixel to the light's centre",
            .params = {},
            .run = exactReference,
            .referenceName = "reference",
            .output = TechniqueOutput::Visibility};
}

Technique softReferenceTechnique() {
    return {.name = "reference-soft",
            .description = "exact soft shadows: the visible fraction of the area light (or of a sun's disk "
                           "on the sky), n x n stratified Embree rays per pixel",
            .params = softReferenceSettingsTable().specs(),
            .run = exactSoftReference,
            .referenceName = "reference-soft",
            .output = TechniqueOutput::Visibility};
}

}  // namespace shadowlab
