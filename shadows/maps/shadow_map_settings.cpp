#include "shadows/maps/shadow_map_settings.h"

namespace shadowlab {

const SettingsTable<BiasSettings>& biasSettingsTable() {
    using S = BiasSettings;
    static const auto table =
        SettingsTable<S>()
            .choice("bias", member(&S::mode),
                    {{"constant", BiasMode::Constant},
                     {"slope-scaled", BiasMode::SlopeScaled, "polygon offset"},
                     {"normal-offset", BiasMode::NormalOffset},
                     {"receiver-plane", BiasMode::ReceiverPlane, "exact for planes, acne in concavities"}})
            .real("constant-bias", member(&S::constantMetres), 0.0, 100.0,
                  "constant, normal-offset: metres the receiver moves towards the light")
            .real("slope-factor", member(&S::slopeFactor), 0.0, 1000.0,
                  "slope-scaled: polygon offset factor; 1 covers a nearest lookup half a texel away")
            .real("slope-units", member(&S::slopeUnits), 0.0, 1e6,
                  "slope-scaled: polygon offset units, in float depth steps")
            .real("normal-offset", member(&S::normalOffsetTexels), 0.0, 1000.0,
                  "normal-offset: texels along the normal at a grazing light");
    return table;
}

const std::vector<Choice<RotationNoise>>& rotationNoiseChoices() {
    static const std::vector<Choice<RotationNoise>> choices = {
        {"hash", RotationNoise::Hash, "hashed from the pixel, the same every frame"},
        {"ign", RotationNoise::InterleavedGradient, "interleaved gradient noise moving with the frame (for temporal=on)"}};
    return choices;
}

const SettingsTable<FilterSettings>& filterSettingsTable() {
    using S = FilterSettings;
    static const auto table =
        SettingsTable<S>()
            .choice("filter", member(&S::kind),
                    {{"nearest", FilterKind::Nearest},
                     {"bilinear", FilterKind::Bilinear, "2x2 PCF"},
                     {"grid", FilterKind::Grid, "NxN PCF"},
                     {"poisson", FilterKind::Poisson, "rotated Poisson disk PCF"}})
            .integer("grid-size", member(&S::gridSize), 2, 15, "grid: taps per side")
            .integer("poisson-taps", member(&S::poissonTaps), 1, 64, "poisson: taps")
            .real("poisson-radius", member(&S::poissonRadiusTexels), 0.0, 64.0, "poisson: radius in texels")
            .choice("poisson-rotation", member(&S::rotation), rotationNoiseChoices(),
                    "poisson: what turns the disk per pixel");
    return table;
}

const SettingsTable<ShadowMapSettings>& shadowMapSettingsTable() {
    using S = ShadowMapSettings;
    static const auto table =
        SettingsTable<S>()
            .include(member(&S::resolution), mapResolutionTable("texels per side of each map"))
            .include(member(&S::bias), biasSettingsTable())
            .choice("layer", member(&S::layer),
                    {{"first", DepthLayer::First},
                     {"second", DepthLayer::Second, "back faces"},
                     {"midpoint", DepthLayer::Midpoint, "average of first and second depth"}})
            .include(member(&S::filter), filterSettingsTable());
    return table;
}

DepthMapSettings depthMapSettings(const ShadowMapSettings& s) {
    return {s.resolution, s.layer, polygonOffsetFor(s.bias), {}};
}

}  // namespace shadowlab
