// The `smoothies` technique (Chan and Durand 2003, "Rendering Fake Soft Shadows with
// Smoothies"), as Cai et al. 2006 (sections 2 and 7.1) compare with it: the hard shadow plus
// outer fins only, weight 1 at the silhouette, all of one global width t_s as seen from the
// light's centre, so the light's size plays no part. One layer; the pipeline is
// fin_shadows.h's.
#include "shadows/fins/fins.h"

#include "shadows/fins/fin_shadows.h"

namespace shadowlab {
namespace {

struct SmoothiesSettings {
    FinMapSettings maps;
    double size = 0.06;   // t_s
};

const SettingsTable<SmoothiesSettings>& smoothiesSettingsTable() {
    using S = SmoothiesSettings;
    static const auto table =
        SettingsTable<S>()
            .include(member(&S::maps), finMapSettingsTable())
            .real("size", member(&S::size), 1e-4, 1.0,
                  "smoothie width as seen from the light's centre, tangent of the angle; "
                  "0.06 is about the built-in disk (radius 0.5 m) seen from 8 m");
    return table;
}

ShadowOutputs runSmoothies(const ShadowInputs& in) {
    const SmoothiesSettings settings = smoothiesSettingsTable().read(in.params);
    FinSettings s = finSettings(in, "smoothies", settings.maps);
    s.style = {.innerFins = false, .edgeWeight = 1.0f, .sizing = {FinSizing::Kind::AngularWidth, settings.size}};
    return renderFinShadows(in, s);
}

}  // namespace

Technique smoothiesTechnique() {
    return {.name = "smoothies",
            .description = "smoothies (Chan and Durand 2003): hard shadow plus outer fins of one global size; "
                           "disk lights",
            .params = smoothiesSettingsTable().specs(),
            .run = runSmoothies,
            .referenceName = "reference-soft",
            .output = TechniqueOutput::Visibility,
            .prepare = prepareEdgeAdjacency};
}

}  // namespace shadowlab
