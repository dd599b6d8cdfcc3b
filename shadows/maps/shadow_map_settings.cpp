#include "shadows/maps/shadow_map_settings.h"

namespace shadowlab {

std::vector<ParamSpec> shadowMapParamSpecs() {
    return {
        integerParam("resolution", 2048, kMinMapResolution, kMaxMapResolution, "texels per side of each map"),
        choiceParam<BiasMode>("bias", "slope-scaled",
                              {{"constant", BiasMode::Constant},
                               {"slope-scaled", BiasMode::SlopeScaled, "polygon offset"},
                               {"normal-offset", BiasMode::NormalOffset},
                               {"receiver-plane", BiasMode::ReceiverPlane, "exact for planes, acne in concavities"}}),
        realParam("constant-bias", 0.05, 0.0, 100.0, "constant, normal-offset: metres the receiver moves towards the light"),
        realParam("slope-factor", 1.5, 0.0, 1000.0,
                  "slope-scaled: polygon offset factor; 1 covers a nearest lookup half a texel away"),
        realParam("slope-units", 4.0, 0.0, 1e6, "slope-scaled: polygon offset units, in float depth steps"),
        realParam("normal-offset", 1.0, 0.0, 1000.0, "normal-offset: texels along the normal at a grazing light"),
        choiceParam<DepthLayer>("layer", "first",
                                {{"first", DepthLayer::First},
                                 {"second", DepthLayer::Second, "back faces"},
                                 {"midpoint", DepthLayer::Midpoint, "average of first and second depth"}}),
        choiceParam<FilterKind>("filter", "nearest",
                                {{"nearest", FilterKind::Nearest},
                                 {"bilinear", FilterKind::Bilinear, "2x2 PCF"},
                                 {"grid", FilterKind::Grid, "NxN PCF"},
                                 {"poisson", FilterKind::Poisson, "rotated Poisson disk PCF"}}),
        integerParam("grid-size", 3, 2, 15, "grid: taps per side"),
        integerParam("poisson-taps", 16, 1, 64, "poisson: taps"),
        realParam("poisson-radius", 1.5, 0.0, 64.0, "poisson: radius in texels"),
    };
}

ShadowMapSettings readShadowMapSettings(const TechniqueParams& p) {
    ShadowMapSettings s;
    s.resolution = p.integer("resolution");
    s.bias.mode = p.choice<BiasMode>("bias");
    s.bias.constantMetres = p.real("constant-bias");
    s.bias.slopeFactor = float(p.real("slope-factor"));
    s.bias.slopeUnits = float(p.real("slope-units"));
    s.bias.normalOffsetTexels = p.real("normal-offset");
    s.layer = p.choice<DepthLayer>("layer");
    s.filter.kind = p.choice<FilterKind>("filter");
    s.filter.gridSize = p.integer("grid-size");
    s.filter.poissonTaps = p.integer("poisson-taps");
    s.filter.poissonRadiusTexels = p.real("poisson-radius");
    return s;
}

DepthMapSettings depthMapSettings(const ShadowMapSettings& s) {
    return {s.resolution, s.layer, polygonOffsetFor(s.bias)};
}

}  // namespace shadowlab
