// The `penumbra-maps` technique (Wyman and Hansen 2003, "Penumbra Maps: Approximate Soft
// Shadows in Real-Time"), as Cai et al. 2006 (sections 2 and 7.1) compare with it: the hard
// shadow plus outer fins only, weight 1 at the silhouette, as wide as the light's radius
// makes the penumbra on the reference receiver plane (eq. 3), so the whole penumbra lies
// outside the hard shadow. One layer; the pipeline is fin_shadows.h's.
#include "shadows/fins/fins.h"

#include "shadows/fins/fin_shadows.h"

namespace shadowlab {
namespace {

ShadowOutputs runPenumbraMaps(const ShadowInputs& in) {
    FinSettings s = finSettings(in, "penumbra-maps", finMapSettingsTable().read(in.params));
    s.style = {.innerFins = false, .edgeWeight = 1.0f, .sizing = {FinSizing::Kind::LightRadius, s.light.radius}};
    return renderFinShadows(in, s);
}

}  // namespace

Technique penumbraMapsTechnique() {
    return {.name = "penumbra-maps",
            .description = "penumbra maps (Wyman and Hansen 2003): hard shadow plus outer fins sized by the "
                           "light; disk lights",
            .params = finMapSettingsTable().specs(),
            .run = runPenumbraMaps,
            .referenceName = "reference-soft",
            .output = TechniqueOutput::Visibility,
            .prepare = prepareEdgeAdjacency};
}

}  // namespace shadowlab
