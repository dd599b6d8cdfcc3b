// The visible fraction of an area light inside a wedge (Assarsson and Akenine-Möller 2003,
// the pixel shader's coverage computation, which the paper looks up in a precomputed 4D
// texture; here computed exactly, per receiver point P and silhouette edge).
//
// Seen from P, the silhouette edges of the light's centre c project onto the light's plane
// as closed loops; the light covered is the part of the light inside them. Counting the
// loops' winding w along the segment from c to each light point x (Green's theorem in
// counting form): w(x) = w(c) - (signed crossings of c -> x with the projected edges), so
//
//   covered area = A [c covered] + sum over edges of sigma_e area(L n R_e),
//
// with R_e the region of the plane beyond the projected edge a -> b seen from c (inside the
// cone from c through a and b, across the edge's line from c) and sigma_e the sign of
// cross(a - c, b - c), times -1 if P is behind the light's plane (the loop then turns the
// other way). [c covered] is the hard shadow of the centre, 1 - V_hard, which the stencil
// pass gives; hence V = V_hard - sum_e coverage_e, coverage_e = sigma_e area(L n R_e) / A.
// Where the silhouettes of several occluders overlap, w counts both and covered can exceed
// what is hidden: the technique's known over-darkening.
//
// In the light's affine coordinates (the light is [-1, 1]^2 or the unit disk; area ratios
// do not change under affine maps):
//   rectangle: R_e is three half-planes; the square is clipped by them (Sutherland-Hodgman)
//     and its area taken by the shoelace formula;
//   disk: area(D n R_e) = area(D n cone) - area(D n triangle(c, a, b)) reduces to the
//     piece [p, q] of the segment inside the circle: (angle(p, q) - |cross(p, q)|) / 2.
// An edge's points at or beyond P's distance from the light's plane hide nothing from P;
// the edge is cut just before it (1e-6 of P's distance), where it projects very far out, so
// the arithmetic is in double.
#pragma once

#include <glm/glm.hpp>

#include "shading/light_sampling.h"

namespace shadowlab {

// As the centre crosses the projected edge a b (between a and b), the cone from it turns
// from one half-plane to the other and coverage_e jumps by exactly side sigma_e, the jump
// of the hard shadow it makes up for; crossing the line outside a b changes nothing.
// Where the centre lies that close to the edge, the stencil's depth test and this
// arithmetic may disagree on it (a pixel of V off by 1 along the hard shadow's boundary);
// hard_boundary.h then takes the stencil's answer, and needs these figures for it.
struct EdgeCoverage {
    double coverage = 0.0;     // coverage_e
    bool nearCentre = false;   // the centre within kNearCentre of the segment a b (light units)
    bool inSpan = false;       // the centre's foot on the edge's line lies between a and b
    double pSide = 0.0;        // sigma_e side: P's side of the plane through the edge and the
                               // centre, oriented by cross(x1 - x0, centre - x0)
};
inline constexpr double kNearCentre = 1e-3;

// coverage_e of the edge x0 -> x1 (as the silhouette walks it) at receiver point p: the
// signed share of the light's area it adds to the covered area.
EdgeCoverage edgeCoverage(const AreaLightPlane& light, const glm::dvec3& p, const glm::dvec3& x0, const glm::dvec3& x1);

}  // namespace shadowlab
