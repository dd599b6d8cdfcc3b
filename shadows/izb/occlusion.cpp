// Irregular z-buffer, stage 6: the exact test of one receiver against one occluder. Aila
// and Laine (2004) test whether the sample lies inside the triangle's
// projection from the light and behind its plane; for a segment from the receiver O to the
// light that is a segment-triangle intersection, evaluated here in double with signed
// volumes (the side tests of Pluecker coordinates).
//
// With A, B, C the vertices relative to O and d the direction to the light, the line
// O + t d passes through the triangle iff the three volumes
//     e_AB = det(A, B, d), e_BC = det(B, C, d), e_CA = det(C, A, d)
// share a sign; their sum is det(B - A, C - A, d) = n . d (n the unnormalised plane normal),
// and the plane is met at t = det(A, B, C) / (n . d).
//
// Why this is robust where it matters:
//  - Watertight: an edge shared by two triangles gives bit-identical volumes of opposite
//    sign in both, since swapping the operands of a cross product negates each rounded
//    component exactly; a zero volume counts as inside (closed edges), so a segment through
//    a shared edge is blocked by at least one of the two triangles and never slips between.
//  - Precise: vertices, origins and the light are floats or near-float doubles, so A, B, C
//    are exact or nearly so, and each volume carries a relative error of a few 2^-53, far
//    below the float rounding the reference's Embree rays carry (about 2^-24). The two
//    disagree only where the segment passes within ~1e-7 of its length from an occluder's
//    edge: ties, which the exact techniques' tests allow right at a shadow boundary.
#include "shadows/izb/izb.h"

namespace shadowlab::izb {
namespace {

double det(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) { return glm::dot(glm::cross(a, b), c); }

}  // namespace

bool segmentBlocked(const glm::dvec3& origin, const glm::dvec3& towardsLight, double tFar,
                    const glm::dvec3 (&triangle)[3]) {
    const glm::dvec3 A = triangle[0] - origin, B = triangle[1] - origin, C = triangle[2] - origin;
    const double eAB = det(A, B, towardsLight), eBC = det(B, C, towardsLight), eCA = det(C, A, towardsLight);
    const double nd = eAB + eBC + eCA;
    // A triangle seen edge-on from the light (nd = 0) covers no area of its projection.
    if (nd == 0.0) return false;
    const double s = nd > 0.0 ? 1.0 : -1.0;
    if (s * eAB < 0.0 || s * eBC < 0.0 || s * eCA < 0.0) return false;
    // 0 <= t <= tFar with t = det(A, B, C) / nd, compared without dividing.
    const double t = s * det(A, B, C), range = s * nd;
    return t >= 0.0 && t <= tFar * range;
}

}  // namespace shadowlab::izb
