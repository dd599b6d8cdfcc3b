// The `fins` technique: multi-layered shadow fins (Cai, Jia, Wang, Hu and Martin 2006,
// "Rendering Soft Shadows using Multi-layered Shadow Fins"): inner and outer fins with the
// edge weight 0.5 of eq. 1, as wide as the light's radius makes the penumbra on the
// reference receiver plane (eq. 3), drawn in light-space layers of about equal numbers of
// silhouette edges (section 4.1). The pipeline is fin_shadows.h's.
#include "shadows/fins/fins.h"

#include "shadows/fins/fin_shadows.h"

namespace shadowlab {
namespace {

// The `layers` parameter's upper bound: the paper uses 16 and finds no scene needing more
// (section 6); past 64 a layer would hold a handful of edges even on the bunny.
constexpr int kMaxLayers = 64;

struct FinsSettings {
    FinMapSettings maps;
    int layers = 16;   // the paper's
};

const SettingsTable<FinsSettings>& finsSettingsTable() {
    using S = FinsSettings;
    static const auto table =
        SettingsTable<S>()
            .include(member(&S::maps), finMapSettingsTable())
            .integer("layers", member(&S::layers), 1, kMaxLayers,
                     "light-space layers of about equal numbers of silhouette edges, section 4.1; "
                     "1 is the single-layer algorithm of section 3");
    return table;
}

ShadowOutputs runFins(const ShadowInputs& in) {
    const FinsSettings settings = finsSettingsTable().read(in.params);
    FinSettings s = finSettings(in, "fins", settings.maps);
    s.style = {.innerFins = true, .edgeWeight = 0.5f, .sizing = {FinSizing::Kind::LightRadius, s.light.radius}};
    s.layers = settings.layers;
    return renderFinShadows(in, s);
}

}  // namespace

Technique finsTechnique() {
    return {.name = "fins",
            .description = "multi-layered shadow fins (Cai et al. 2006): inner and outer fins, penumbra maps "
                           "per layer, refined "
            "illuminance buffer; disk lights",
            .params = finsSettingsTable().specs(),
            .run = runFins,
            .referenceName = "reference-soft",
            .output = TechniqueOutput::Visibility,
            .prepare = prepareEdgeAdjacency};
}

}  // namespace shadowlab
