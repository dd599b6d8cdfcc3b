// The form factor from a differential area to a polygon: the share of the light a
// Lambertian polygon of unit radiance sends that lands on a small receiver, or, the other
// way round, what the receiver at x with unit normal n sees of the polygon, weighted by
// cosines. A diffuse emitter of radiance B lights x with irradiance E = pi B F, which a
// diffuse receiver of reflectance rho reflects as radiance rho B F: Gibson et al. 2003's
// radiance transfer L_ij (section 5) with full visibility, F by the closed form its
// references 4 and 28 give (Cohen and Wallace 1993, Sillion and Puech 1994):
//
//   F = 1 / (2 pi) * sum over edges (v_k, v_k+1) of  theta_k  n . unit(r_k x r_k+1),
//   r_k = v_k - x,  theta_k the angle between r_k and r_k+1,
//
// the contour integral of Lambert's formula, exact for the polygon above x's tangent plane.
// The polygon is first clipped to that half-space, so a patch that straddles the receiver's
// horizon counts only where the receiver can see it.
#pragma once

#include <span>

#include <glm/glm.hpp>

namespace shadowlab {

// F from the receiver at x (unit normal n) to the convex or concave planar polygon with
// the given corners, counter-clockwise seen from its emitting side (the meshes' front
// face). 0 where x is on or behind the polygon's plane, or the polygon lies on or below
// x's tangent plane; in [0, 1] otherwise.
double pointToPolygonFormFactor(const glm::dvec3& x, const glm::dvec3& n, std::span<const glm::dvec3> polygon);

}  // namespace shadowlab
