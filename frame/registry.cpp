// The registry: every technique of every family, in the order `shadowlab techniques` lists
// them. The one file that includes every family (docs/architecture.md).
#include "frame/registry.h"

#include <stdexcept>

#include "shadows/backprojection/backprojection.h"
#include "shadows/deep/deep_techniques.h"
#include "shadows/environment/environment_techniques.h"
#include "shadows/filtered/soft_shadow_techniques.h"
#include "shadows/fins/fins.h"
#include "shadows/hybrid/izb_pcss.h"
#include "shadows/izb/izb.h"
#include "shadows/maps/shadow_map_techniques.h"
#include "shadows/planar/planar.h"
#include "shadows/projected/projected_texture.h"
#include "shadows/raytraced/ray_traced.h"
#include "shadows/reference/reference_techniques.h"
#include "shadows/screen/contact_shadows.h"
#include "shadows/temporal/confidence_reprojection.h"
#include "shadows/temporal/temporal_accumulation.h"
#include "shadows/virtual/virtual_shadow_map.h"
#include "shadows/volumes/shadow_volume.h"
#include "shadows/wedges/soft_shadow_volumes.h"

namespace shadowlab {

const std::vector<Technique>& techniques() {
    // The references and `unshadowed` keep the whole scene: they have no caster level of detail.
    static const std::vector<Technique> all = {
        unshadowedTechnique(),
        referenceTechnique(),
        softReferenceTechnique(),
        withCasterLod(withTemporalAccumulation(rayTracedTechnique())),
        withCasterLod(withTemporalAccumulation(shadowMapTechnique())),
        withCasterLod(confidenceReprojectionTechnique()),
        withCasterLod(cascadedShadowMapTechnique()),
        withCasterLod(virtualShadowMapTechnique()),
        withCasterLod(irregularZBufferTechnique()),
        withCasterLod(contactShadowsTechnique()),
        withCasterLod(shadowVolumeTechnique()),
        withCasterLod(planarTechnique()),
        withCasterLod(projectedTextureTechnique()),
        withCasterLod(withTemporalAccumulation(pcssTechnique())),
        withCasterLod(contactHardeningTechnique()),
        withCasterLod(izbPcssTechnique()),
        withCasterLod(filteredShadowMapTechnique(MomentKind::Variance)),
        withCasterLod(filteredShadowMapTechnique(MomentKind::Exponential)),
        withCasterLod(filteredShadowMapTechnique(MomentKind::ExponentialVariance)),
        withCasterLod(filteredShadowMapTechnique(MomentKind::Hamburger4)),
        withCasterLod(multiSampleTechnique()),
        withCasterLod(backprojectionTechnique()),
        withCasterLod(finsTechnique()),
        withCasterLod(smoothiesTechnique()),
        withCasterLod(penumbraMapsTechnique()),
        withCasterLod(softShadowVolumeTechnique()),
        withCasterLod(colouredShadowMapTechnique()),
        withCasterLod(opacityShadowMapsTechnique()),
        withCasterLod(deepShadowMapsTechnique()),
        withCasterLod(adaptiveVolumetricShadowMapsTechnique()),
        withCasterLod(environmentAdditiveTechnique()),
        withCasterLod(environmentSubtractiveTechnique()),
        environmentLightsReferenceTechnique(),
        environmentReferenceTechnique(),
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
