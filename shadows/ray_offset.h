// How far a shadow ray starts from the surface point it leaves, so that it does not hit the
// surface it starts on. The exact reference and the techniques that test visibility exactly
// (the irregular z-buffer) use the same offset, so they agree bit for bit on what counts as
// self-shadowing.
#pragma once

#include <glm/glm.hpp>

#include "scenes/scene.h"

namespace shadowlab {

// The diagonal of the bounding box of all vertices (m): the scene scale S below.
double sceneDiagonal(const WorldGeometry& world);

// How far a shadow ray's origin moves from P along N: 32 u S with u = 2^-24 and
// S = max(max_k |P_k|, sceneDiagonal), derived in ray_offset.cpp. The same distance is
// taken off the far end of a ray to a light point.
double shadowRayOffset(const glm::vec3& P, double sceneDiagonal);
// The offset per unit of S: 32 u (vector code that computes S itself multiplies by it).
inline constexpr double kShadowRayOffsetPerScale = 32.0 * 0x1p-24;

}  // namespace shadowlab
