#include "shadows/technique.h"

#include <stdexcept>

#include "shadows/fins/fins.h"
#include "shadows/izb/izb.h"
#include "shadows/planar/planar.h"
#include "shadows/reference/reference.h"
#include "shadows/maps/shadow_map_techniques.h"
#include "shadows/volumes/shadow_volume.h"
#include "shadows/filtered/soft_shadow_techniques.h"

namespace shadowlab {
namespace {

ShadowOutputs unshadowed(const ShadowInputs& in) {
    ShadowOutputs out;
    out.visibility.resize(in.gbuffer.pixelCount());
    for (size_t k = 0; k < out.visibility.size(); ++k) out.visibility[k] = in.gbuffer.hit[k] ? 1.0f : 0.0f;
    return out;
}

ShadowOutputs exactReference(const ShadowInputs& in) {
    const ReferenceVisibility reference(in.world());
    ShadowOutputs out;
    out.visibility = reference.visibility(in.gbuffer, pointLightFor(in.light), {.progress = in.progress});
    return out;
}

// The soft shadows' reference: the visible fraction of the area light itself, from n x n
// stratified samples (reference.h); point and directional lights give hard shadows.
ShadowOutputs exactSoftReference(const ShadowInputs& in) {
    const ReferenceVisibility reference(in.world());
    ShadowOutputs out;
    const int samplesPerAxis = in.params.integer("samples-per-axis", 1, 256);
    out.visibility = reference.visibility(in.gbuffer, in.light, {.areaSamplesPerAxis = samplesPerAxis, .progress = in.progress});
    return out;
}

// Soft-shadow techniques are scored against the area light's visible fraction.
Technique scoredAgainstSoftReference(Technique t) {
    t.referenceName = "reference-soft";
    return t;
}

}  // namespace

const std::vector<Technique>& techniques() {
    static const std::vector<Technique> all = {
        {"none", "no shadows: V = 1 on every surface", {}, unshadowed},
        {"reference", "exact hard shadows: one Embree shadow ray per pixel to the light's centre", {}, exactReference},
        {"reference-soft", "exact soft shadows: the visible fraction of the area light, n x n stratified Embree rays per pixel",
         {{"samples-per-axis", "32", "n: n x n samples on the light (1..256)"}}, exactSoftReference, "reference-soft"},
        shadowMapTechnique(),
        cascadedShadowMapTechnique(),
        {"izb", "irregular z-buffer: occluders rasterized at the camera's samples, exact hard shadows", irregularZBufferParams(), irregularZBuffer},
        shadowVolumeTechnique(),
        planarTechnique(),
        scoredAgainstSoftReference(pcssTechnique()),
        scoredAgainstSoftReference(filteredShadowMapTechnique(MomentKind::Variance)),
        scoredAgainstSoftReference(filteredShadowMapTechnique(MomentKind::Exponential)),
        scoredAgainstSoftReference(filteredShadowMapTechnique(MomentKind::ExponentialVariance)),
        scoredAgainstSoftReference(filteredShadowMapTechnique(MomentKind::Hamburger4)),
        scoredAgainstSoftReference(multiSampleTechnique()),
        scoredAgainstSoftReference(finsTechnique()),
        scoredAgainstSoftReference(smoothiesTechnique()),
        scoredAgainstSoftReference(penumbraMapsTechnique()),
    };
    return all;
}

const Technique& findTechnique(const std::string& name) {
    std::string known;
    for (const Technique& t : techniques()) {
        if (t.name == name) return t;
        known += (known.empty() ? "" : ", ") + t.name;
    }
    throw std::invalid_argument("unknown technique '" + name + "' (known: " + known + ")");
}

Light pointLightFor(const Light& light) {
    if (light.type != LightType::Disk && light.type != LightType::Rectangle) return light;
    Light point = light;
    point.type = LightType::Point;
    return point;
}

}  // namespace shadowlab
