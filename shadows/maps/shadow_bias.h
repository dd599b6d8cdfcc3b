// Shadow-map bias (Real-Time Rendering, 4th ed., section 7.4, Figures 7.13 and 7.24, and
// section 7.5): the ways of keeping a lit surface from shadowing itself ("acne") because
// the map stores its depth at texel centres, not where the receiver is looked up.
//
//   constant        the receiver moves a fixed distance towards the light [RTR 7.4].
//   slope-scaled    the map's triangles move away from the light in proportion to their
//                   depth slope, with glPolygonOffset (PipelineState::offset) [RTR 7.4].
//   normal-offset   the receiver moves along its normal by a number of texels times the
//                   sine of the light angle (Holbert), which also moves its texel, plus
//                   the constant bias for surfaces facing the light [RTR 7.4].
//   receiver-plane  the receiver's own plane gives its depth at every texel centre the
//                   filter compares against (Isidoro 2006, Tuft 2011; RTR 7.5, Figure 7.24
//                   middle). Exact for planar receivers, including perspective maps: a
//                   projective map takes planes to planes, so window depth is linear in
//                   texel coordinates. What remains is the rasterizer's own error, bounded
//                   in shadow_bias.cpp. Fails in concavities finer than a texel (the
//                   bunny: 0.29% acne against 0.008% for slope-scaled).
//
// The default is slope-scaled with factor 1.5 and 4 units: a nearest lookup lands at most
// half a texel from the texel centre in x and y, where a planar occluder's depth differs
// by at most max|dz/dx, dz/dy| (factor 1); the extra half texel covers snapping and
// the concave creases of meshes finer than the map. On sphere-box and bunny it has the
// least acne and leaks of the four together (docs/shadow-maps.md gives the figures).
#pragma once

#include <glm/glm.hpp>

#include "raster/pipeline_state.h"
#include "shadows/depth_map.h"

namespace shadowlab {

enum class BiasMode { Constant, SlopeScaled, NormalOffset, ReceiverPlane };

struct BiasSettings {
    BiasMode mode = BiasMode::SlopeScaled;
    double constantMetres = 0.05;        // constant, normal-offset: distance towards the light, m
    float slopeFactor = 1.5f;            // slope-scaled: polygon offset factor (texels of slope)
    float slopeUnits = 4.0f;             // slope-scaled: polygon offset units (float depth steps)
    double normalOffsetTexels = 1.0;     // normal-offset: texels at a grazing light
};

// The polygon offset the map is drawn with (zero except in slope-scaled mode).
raster::PolygonOffset polygonOffsetFor(const BiasSettings& bias);

// A receiver as the map sees it.
struct MapReceiver {
    glm::dvec2 texel{0.0};        // where it falls in the map, texel units
    double depth = 0.0;           // its window depth there, after the bias
    glm::dvec2 depthSlope{0.0};   // d depth / d texel of its plane (receiver-plane only, else 0)
    double tolerance = 0.0;       // added to the stored depth before comparing (receiver-plane)

    // The receiver's (plane's) depth at texel position t.
    double depthAt(const glm::dvec2& t) const { return depth + glm::dot(depthSlope, t - texel); }
    // Lit by texel (x, y) of the map: not farther from the light than what the map stores.
    // An empty texel (the cleared 1) holds no occluder, even where the receiver's plane,
    // extrapolated past the farthest receiver, runs beyond the far plane.
    bool litBy(const DepthMap& map, int x, int y) const { return litByStored(map.at(x, y), x, y); }
    // The same for `stored`, the depth texel (x, y) holds wherever it is kept (a virtual
    // map's page).
    bool litByStored(float stored, int x, int y) const {
        return stored >= 1.0f || depthAt(glm::dvec2(x + 0.5, y + 0.5)) <= double(stored) + tolerance;
    }
};

// Whether mapReceiver() reads its unitTowardsLight (constant and normal-offset bias move the
// receiver towards the light; the others leave it where it is).
inline bool needsLightDirection(const BiasSettings& bias) {
    return bias.mode == BiasMode::Constant || bias.mode == BiasMode::NormalOffset;
}

// P and N in world space, unitTowardsLight the unit direction from P to the light (read
// only where needsLightDirection()).
MapReceiver mapReceiver(const DepthMap& map, const glm::dvec3& P, const glm::dvec3& N,
                        const glm::dvec3& unitTowardsLight, const BiasSettings& bias);

// The same for a light at lightPosition, normalising the direction only where it is read.
inline MapReceiver mapReceiverFromPoint(const DepthMap& map, const glm::dvec3& P, const glm::dvec3& N,
                                        const glm::dvec3& lightPosition, const BiasSettings& bias) {
    return mapReceiver(map, P, N, needsLightDirection(bias) ? glm::normalize(lightPosition - P) : glm::dvec3(0.0), bias);
}

// The world-space width of one texel at P (distance between neighbouring texel centres).
double texelWorldSize(const DepthMap& map, const glm::dvec3& P);

}  // namespace shadowlab
