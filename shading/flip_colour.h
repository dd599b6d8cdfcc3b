// FLIP's colour pipeline (Andersson et al., "FLIP: A Difference Evaluator for Alternating
// Images", HPG 2020, sec. "Color pipeline"): the two images in the opponent space YyCxCz,
// each channel filtered by its contrast sensitivity function at the viewing distance, back to
// linear RGB clamped to the display's gamut, into CIELab with the Hunt adjustment, and the
// HyAB distance of the two, compressed and redistributed into [0, 1].
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "shading/flip_filter.h"

namespace shadowlab::flip {

// The paper's constants (sec. "Color pipeline"): the colour difference is raised to q_c, and
// its lowest p_c of the range (relative to the largest difference, green against blue) is
// stretched over [0, p_t].
inline constexpr float kColourExponent = 0.7f;         // q_c
inline constexpr float kColourRangeSplit = 0.4f;       // p_c
inline constexpr float kColourRangeTarget = 0.95f;     // p_t

// The opponent channels in the paper's order: achromatic Yy, red-green Cx, blue-yellow Cz.
enum class Opponent { Yy, Cx, Cz };

// The CSF of one channel as a spatial filter at `pixelsPerDegree` (sec. "Spatial filtering"):
// a sum of two Gaussians a_i sqrt(pi / b_i) exp(-pi^2 x^2 / b_i), x in degrees, which in two
// dimensions is a sum of products of 1D kernels. `terms` holds one 1D kernel per Gaussian
// (one for Yy and Cx, whose second Gaussian has a_2 = 0; two for Cz), all of one radius,
// ceil(3 sigma) of the widest Gaussian of the three channels, and scaled so that the 2D filter
// sum_i terms[i](x) terms[i](y) sums to 1 (a DC gain of 1: flat colour passes unchanged).
struct CsfFilter {
    std::vector<Kernel> terms;
};
CsfFilter csfFilter(Opponent channel, float pixelsPerDegree);

// Linear RGB (sRGB primaries, D65) <-> YyCxCz, the linearised CIELab of Johnson and
// Fairchild that FLIP filters in: Yy = 116 Y/Yn - 16, Cx = 500 (X/Xn - Y/Yn),
// Cz = 200 (Y/Yn - Z/Zn), with the display's white (1, 1, 1) as (Xn, Yn, Zn).
glm::vec3 linearRgbToYyCxCz(const glm::vec3& rgb);
glm::vec3 yyCxCzToLinearRgb(const glm::vec3& yyCxCz);
// CIELab of a linear RGB colour with the Hunt adjustment (sec. "Perceptually uniform color
// space"): a and b scaled by 0.01 L, so that dark colours differ less in chroma.
glm::vec3 huntLab(const glm::vec3& rgb);
// HyAB (Abasi et al. 2020): |L1 - L2| + ||(a1, b1) - (a2, b2)||.
float hyab(const glm::vec3& lab1, const glm::vec3& lab2);
// The largest difference, HyAB(green, blue)^q_c in Hunt-adjusted CIELab.
float maxColourDifference();
// HyAB^q_c -> [0, 1]: [0, p_c cmax) linearly onto [0, p_t), [p_c cmax, cmax] onto [p_t, 1],
// with cmax = maxColourDifference().
float redistributeColourDifference(float compressed, float cmax);

// Per pixel, the redistributed colour difference Delta E_c of `test` against `reference`
// (display-referred linear RGB in [0, 1], row-major, width x height each). Filtering at
// `pixelsPerDegree`; rows in parallel, the same bits for any thread count.
Plane colourDifference(const std::vector<glm::vec3>& reference, const std::vector<glm::vec3>& test, int width,
                       int height, float pixelsPerDegree);

}  // namespace shadowlab::flip
