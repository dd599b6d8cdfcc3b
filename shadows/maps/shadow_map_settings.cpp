#include "shadows/maps/shadow_map_settings.h"

namespace shadowlab {

std::vector<ParamSpec> shadowMapParamSpecs() {
    return {
        {"resolution", "2048", "texels per side of each map (16..8192)"},
        {"bias", "slope-scaled",
         "constant | slope-scaled (polygon offset) | normal-offset | receiver-plane (exact for planes, acne in concavities)"},
        {"constant-bias", "0.05", "constant, normal-offset: metres the receiver moves towards the light"},
        {"slope-factor", "1.5", "slope-scaled: polygon offset factor (1 covers a nearest lookup half a texel away)"},
        {"slope-units", "4", "slope-scaled: polygon offset units (float depth steps)"},
        {"normal-offset", "1", "normal-offset: texels along the normal at a grazing light"},
        {"layer", "first", "first | second (back faces) | midpoint (average of first and second depth)"},
        {"filter", "nearest", "nearest | bilinear (2x2 PCF) | grid (NxN PCF) | poisson (rotated Poisson disk PCF)"},
        {"grid-size", "3", "grid: taps per side (2..15)"},
        {"poisson-taps", "16", "poisson: taps (1..64)"},
        {"poisson-radius", "1.5", "poisson: radius in texels"},
    };
}

ShadowMapSettings readShadowMapSettings(const TechniqueParams& p) {
    ShadowMapSettings s;
    s.resolution = p.integer("resolution", 16, 8192);
    const std::string bias = p.choice("bias", {"constant", "slope-scaled", "normal-offset", "receiver-plane"});
    s.bias.mode = bias == "constant"        ? BiasMode::Constant
                  : bias == "slope-scaled"  ? BiasMode::SlopeScaled
                  : bias == "normal-offset" ? BiasMode::NormalOffset
                                            : BiasMode::ReceiverPlane;
    s.bias.constantMetres = p.real("constant-bias", 0.0, 100.0);
    s.bias.slopeFactor = float(p.real("slope-factor", 0.0, 1000.0));
    s.bias.slopeUnits = float(p.real("slope-units", 0.0, 1e6));
    s.bias.normalOffsetTexels = p.real("normal-offset", 0.0, 1000.0);
    const std::string layer = p.choice("layer", {"first", "second", "midpoint"});
    s.layer = layer == "first" ? DepthLayer::First : layer == "second" ? DepthLayer::Second : DepthLayer::Midpoint;
    const std::string filter = p.choice("filter", {"nearest", "bilinear", "grid", "poisson"});
    s.filter.kind = filter == "nearest"    ? FilterKind::Nearest
                    : filter == "bilinear" ? FilterKind::Bilinear
                    : filter == "grid"     ? FilterKind::Grid
                                           : FilterKind::Poisson;
    s.filter.gridSize = p.integer("grid-size", 2, 15);
    s.filter.poissonTaps = p.integer("poisson-taps", 1, 64);
    s.filter.poissonRadiusTexels = p.real("poisson-radius", 0.0, 64.0);
    return s;
}

DepthMapSettings depthMapSettings(const ShadowMapSettings& s) {
    return {s.resolution, s.layer, polygonOffsetFor(s.bias)};
}

}  // namespace shadowlab
