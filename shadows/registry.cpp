// The registry: every technique of every family, in the order `shadowlab techniques` lists
// them. The one core file that includes the families (docs/architecture.md).
#include <stdexcept>

#include "shadows/technique.h"
#include "shadows/filtered/soft_shadow_techniques.h"
#include "shadows/fins/fins.h"
#include "shadows/izb/izb.h"
#include "shadows/maps/shadow_map_techniques.h"
#include "shadows/planar/planar.h"
#include "shadows/reference/reference_techniques.h"
#include "shadows/volumes/shadow_volume.h"

namespace shadowlab {
namespace {

// Soft-shadow techniques are scored against the area light's visible fraction.
Technique scoredAgainstSoftReference(Technique t) {
    t.referenceName = "reference-soft";
    return t;
}

}  // namespace

const std::vector<Technique>& techniques() {
    static const std::vector<Technique> all = {
        unshadowedTechnique(),
        referenceTechnique(),
        softReferenceTechnique(),
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

}  // namespace shadowlab
