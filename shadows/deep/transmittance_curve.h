// Stage 2: a texel's transmittance as a function of depth, T(z), the light that reaches
// depth z along the texel's ray (Lokovic and Veach 2000, section 3: the "visibility
// function"). From the texel's events (light_layers.h) the optical depth tau(z) steps up by
// each surface's share and rises linearly across each volume piece (exact in the window
// depth of a directional light's view, which is affine in distance; from a point or spot
// light within about 1% of a piece's share, light_layers.cpp); T is exp(-tau) at the
// vertices where anything changes and linear between them (within 1.3e-3 of the
// exponential inside a piece). A surface is a vertical step: two vertices at its
// depth, the value in front of it, then the value behind it.
#pragma once

#include <span>
#include <vector>

#include "shadows/deep/light_layers.h"

namespace shadowlab {

struct CurveVertex {
    float depth, transmittance;
};

// Makes texels' exact curves, keeping its working memory from one texel to the next (one
// per task).
class ExactCurves {
public:
    // Texel t's exact curve into `out` (cleared first); empty where nothing translucent
    // lies in front of the opaque surface.
    void build(const VolumetricLayers& layers, size_t texel, std::vector<CurveVertex>& out);

private:
    // Where tau(z) changes: a jump (a surface) or a change of slope (a volume piece's ends).
    struct Breakpoint {
        float depth;
        double jump, slopeChange;
    };
    std::vector<Breakpoint> points_;
};

// The optical depth of texel t's events in front of depth z (a volume piece counts the part
// in front of z): what opacity shadow maps sample at their slices.
double opticalDepthBefore(const VolumetricLayers& layers, size_t texel, double z);

// T(z) of a curve: 1 in front of its first vertex, linear between vertices, the last value
// behind the last; at a step's own depth the value in front of it, so a receiver on a
// translucent surface is not shadowed by that surface.
float transmittanceAt(std::span<const CurveVertex> curve, float z);

}  // namespace shadowlab
