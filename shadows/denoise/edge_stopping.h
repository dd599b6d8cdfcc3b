// The edge-stopping functions of SVGF's wavelet passes (Schied et al. 2017, section 4.3,
// eqs. 3-5): a neighbour q weighs less the farther its depth lies from the plane the
// pixel p's depth gradient predicts, the more its normal turns away, and the more its V
// differs from p's in units of p's standard deviation: noise (a large sigma) is smoothed,
// an edge the variance does not explain (a hard shadow's border) is kept.
#pragma once

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "raster/portable_math.h"

namespace shadowlab {

struct EdgeStopping {
    float sigmaDepth = 1.0f;        // sigma_z (eq. 3)
    float sigmaNormal = 128.0f;     // sigma_n, the cosine's exponent (eq. 4)
    float sigmaLuminance = 4.0f;    // sigma_l (eq. 5); here the signal is V
};

inline constexpr float kEdgeEpsilon = 1e-6f;   // keeps eqs. 3 and 5 finite where the scale is 0

// exp and pow are the portable ones (raster/portable_math.h): libm's differ in the last bit
// from one x86 CPU to another, and every weight reaches the output.

// eq. 3: exp(-|z(p) - z(q)| / (sigma_z |grad z(p) . (p - q)| + eps)).
inline float depthWeight(float zp, float zq, glm::vec2 gradient, glm::vec2 offset, float sigma) {
    return float(portable::exp(-std::abs(zp - zq) / (sigma * std::abs(glm::dot(gradient, offset)) + kEdgeEpsilon)));
}

// eq. 4: max(0, n(p) . n(q))^sigma_n.
inline float normalWeight(const glm::vec3& np, const glm::vec3& nq, float sigma) {
    return float(portable::pow(std::max(0.0f, glm::dot(np, nq)), sigma));
}

// eq. 5: exp(-|l(p) - l(q)| / (sigma_l sqrt(variance(p)) + eps)), the variance prefiltered.
inline float signalWeight(float vp, float vq, float variance, float sigma) {
    return float(portable::exp(-std::abs(vp - vq) / (sigma * std::sqrt(std::max(variance, 0.0f)) + kEdgeEpsilon)));
}

}  // namespace shadowlab
