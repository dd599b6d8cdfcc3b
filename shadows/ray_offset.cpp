// The shadow-ray offset shared by the exact reference and the techniques that test
// visibility exactly (the irregular z-buffer), and why it is 32 u S.
#include "shadows/ray_offset.h"

#include <algorithm>
#include <cmath>

namespace shadowlab {

// A shadow ray started exactly at P can hit the triangle P lies on at t ~ 0 when rounding
// puts P, or Embree's computed plane distance, a hair on the wrong side: self-shadowing
// ("acne"). Moving the origin along N by more than the worst such error removes it. With
// u = 2^-24 (unit roundoff of float) and S = max(max_k |P_k|, D), D the diagonal of the
// scene's bounding box in metres, the errors in the signed distance from the ray origin to
// P's own plane are:
//  1. P is the exact surface point rounded to float (buildGBuffer): each component is off
//     by <= u |P_k|, so the distance by <= |N|_1 u max_k |P_k| <= sqrt(3) u S.
//  2. The origin P + offset N is rounded to float again: <= sqrt(3) u S.
//  3. Embree's Pluecker test works in float on the triangle's vertices translated to the
//     ray origin (|v - origin| <= triangle size <= D): one subtraction, a cross product
//     of edges and a dot product. By the usual error bounds for these (Higham, Accuracy
//     and Stability of Numerical Algorithms, 2nd ed., section 3.1) the distance it
//     evaluates is off by about 3 u D (translation, dot product) plus 2 u D / sin(alpha)
//     (cross product of edges meeting at angle alpha): about 8 u D for a smallest angle
//     of 30 degrees, more for slivers.
// Total about (2 sqrt(3) + 8) u S < 12 u S. We use 32 u S = 16 * 2^-23 * S, at least 16
// float ulps of S and almost three times the estimate. tests/shadows/reference/test_reference.cpp
// shows the need: with no offset nearly every point of its receivers is shadowed by
// itself; 1 u S already suffices there. The cost is small: for a 10 m
// scene the origin moves 19 micrometres, far below a pixel's footprint, so contact
// shadows of the reference do not visibly detach (peter-panning).
// The same distance is taken off the far end of a ray to a light point, so a light
// placed on a surface (a lamp on a ceiling) is not shadowed by that surface.
// kShadowRayOffsetPerScale (ray_offset.h) is that 32 u.
double shadowRayOffset(const glm::vec3& P, double sceneDiagonal) {
    const double largestCoordinate =
        std::max({std::abs(double(P.x)), std::abs(double(P.y)), std::abs(double(P.z))});
    const double scale = std::max(largestCoordinate, sceneDiagonal);
    return kShadowRayOffsetPerScale * scale;
}

double sceneDiagonal(const WorldGeometry& world) {
    if (world.positions.empty()) return 0.0;
    glm::dvec3 lo(world.positions[0]), hi(world.positions[0]);
    for (const glm::vec3& p : world.positions) lo = glm::min(lo, glm::dvec3(p)), hi = glm::max(hi, glm::dvec3(p));
    return glm::length(hi - lo);
}

}  // namespace shadowlab
