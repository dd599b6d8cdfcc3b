// The `smoothies` technique (Chan and Durand 2003, "Rendering Fake Soft Shadows with
// Smoothies"), as Cai et al. 2006 (sections 2 and 7.1) compare with it: the hard shadow plus
// outer fins only, weight 1 at the silhouette, all of one global width t_s as seen from the
// light's centre, so the light's size plays no part. One layer; the pipeline is
// fin_shadows.h's.
#include "shadows/fins/fins.h"

#include "shadows/fins/fin_shadows.h"

namespace shadowlab {
namespace {

ShadowOutputs runSmoothies(const ShadowInputs& in) {
    FinSettings s = readFinSettings(in, "smoothies");
    s.style = {.innerFins = false, .edgeWeight = 1.0f, .sizing = {FinSizing::Kind::AngularWidth, in.params.real("size")}};
    return renderFinShadows(in, s);
}

}  // namespace

Technique smoothiesTechnique() {
    std::vector<ParamSpec> params = finShadowParams();
    params.push_back(realParam("size", 0.06, 1e-4, 1.0,
                               "smoothie width as seen from the light's centre, tangent of the angle; "
                               "0.06 is about the built-in disk (radius 0.5 m) seen from 8 m"));
    return {.name = "smoothies",
            .description = "smoothies (Chan and Durand 2003): hard shadow plus outer fins of one global size; "
                           "disk lights",
            .params = params,
            .run = runSmoothies,
            .referenceName = "reference-soft",
            .output = TechniqueOutput::Visibility,
            .prepare = prepareEdgeAdjacency};
}

}  // namespace shadowlab
