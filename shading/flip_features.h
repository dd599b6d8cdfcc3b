// FLIP's feature pipeline (Andersson et al. 2020, sec. "Feature pipeline"): edges and points
// of the achromatic channel, found by the first and second derivatives of a Gaussian whose
// width follows the viewing distance; the difference of their magnitudes between the two
// images is the feature difference Delta E_f in [0, 1].
#pragma once

#include <vector>

#include "shading/flip_filter.h"

namespace shadowlab::flip {

// The paper's constants: the Gaussian's sigma is half of w degrees, and Delta E_f is the
// larger of the edge and point differences over sqrt 2, raised to q_f.
inline constexpr float kFeatureWidthDegrees = 0.082f;   // w
inline constexpr float kFeatureExponent = 0.5f;         // q_f

// The 1D kernels of the detectors, radius ceil(3 sigma), sigma = 0.5 w pixelsPerDegree pixels:
// the Gaussian g (summing to 1), its first derivative (positive taps summing to 1, negative to
// -1) and its second (likewise), normalised so that a step or a point of full contrast gives a
// response of the same size at any sigma.
struct FeatureKernels {
    Kernel gaussian, edge, point;
};
FeatureKernels featureKernels(float pixelsPerDegree);

// Per pixel, Delta E_f between two achromatic images (normalised luminance Y / Y_n in [0, 1],
// row-major, width x height each).
Plane featureDifference(const Plane& reference, const Plane& test, float pixelsPerDegree);

}  // namespace shadowlab::flip
