// The BRDF half of the split sum (Karis 2013, "Real Shading in Unreal Engine 4", section
// "Image-based lighting"): a GGX surface under distant light reflects
//
//     integral L(l) f(l, v) (n . l) dl  ~=  P(r) (F0 A(n . v, alpha) + B(n . v, alpha)),
//
// P the prefiltered map of prefiltered_lobe.h (the lobe-weighted mean of L about the mirror
// direction r) and A, B the directional albedo of the BRDF (shading/microfacet_ggx.h) split by
// Schlick's Fresnel: with w = (1 - v . h)^5,
//
//     A = integral f/F (1 - w) (n . l) dl,   B = integral f/F w (n . l) dl,
//
// so F0 A + B is exactly the albedo for a Fresnel reflectance F0 (the split is the only
// approximation, and under a constant environment there is none). A + B < 1 for rough
// surfaces: single scattering loses the light that bounces between microfacets.
//
// Tabulated on a size x size grid of cell centres in (n . v, alpha) over (0, 1]^2, each entry
// a deterministic quadrature in the half vector h: u in (0, 1) maps to the GGX angle of h by
// the inverse of its cosine-weighted CDF, tan^2 theta_h = alpha^2 u / (1 - u), so that
// du dphi / (2 pi) = D(h) (n . h) dh and the integrand f (n . l) / (D (n . h) / (4 v . h))
// = 4 V F (n . l) (v . h) / (n . h) has no peak (V the Smith visibility); a midpoint rule in
// s, u = sin^2(pi s / 2), resolves both ends of u. Read bilinearly.
#pragma once

#include <vector>

#include <glm/glm.hpp>

namespace shadowlab {

struct SplitSumTable {
    int size = 0;
    std::vector<float> scale, bias;   // A and B at (cosV, alpha) = ((i + 1/2) / size, (j + 1/2) / size), index j * size + i

    size_t index(int i, int j) const { return size_t(j) * size_t(size) + size_t(i); }
};

// Throws std::invalid_argument unless 2 <= size <= 1024.
SplitSumTable buildSplitSumTable(int size = 32);

// (A, B) at n . v and alpha, bilinear between the cell centres and clamped to the outermost
// (n . v below 1 / (2 size) takes the first column's values).
glm::dvec2 lookupSplitSum(const SplitSumTable& table, double cosV, double alpha);

}  // namespace shadowlab
