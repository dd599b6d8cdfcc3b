// The GGX (Trowbridge-Reitz) microfacet BRDF, the Torrance-Sparrow form
//
//     f(l, v) = D(h) G2(l, v) F(v . h) / (4 (n . l) (n . v)),   h = normalize(l + v),
//
// with roughness alpha (GGX's alpha; alpha = 0 is a mirror). One definition, read by the
// shading of GGX materials and by the split-sum table (shading/environment/split_sum_table.h),
// written for float and double alike (T).
//   D   the GGX distribution of normals (Walter et al. 2007, "Microfacet Models for Refraction
//       through Rough Surfaces", eq. 33);
//   G2  Smith's height-correlated masking-shadowing (Heitz 2014, "Understanding the
//       Masking-Shadowing Function in Microfacet-Based BRDFs", eq. 99), kept as the visibility
//       V = G2 / (4 (n . l) (n . v)), which is finite where n . l or n . v goes to 0;
//   F   Schlick's approximation F0 + (1 - F0) (1 - v . h)^5 (Schlick 1994).
#pragma once

#include <cmath>

namespace shadowlab {

// D from cos^2 of the angle between n and h and alpha^2 (the form the prefilter needs).
template <class T>
T ggxDistributionFromCos2(T cos2ThetaH, T alpha2) {
    constexpr T kPi = T(3.141592653589793);
    const T denominator = cos2ThetaH * (alpha2 - T(1)) + T(1);
    return alpha2 / (kPi * denominator * denominator);
}

template <class T>
T ggxDistribution(T cosThetaH, T alpha) {
    return cosThetaH > T(0) ? ggxDistributionFromCos2(cosThetaH * cosThetaH, alpha * alpha) : T(0);
}

// V = G2 / (4 (n . l) (n . v)) for n . l, n . v in (0, 1].
template <class T>
T smithVisibility(T cosL, T cosV, T alpha) {
    const T alpha2 = alpha * alpha;
    const T lambdaL = cosV * std::sqrt(cosL * cosL * (T(1) - alpha2) + alpha2);
    const T lambdaV = cosL * std::sqrt(cosV * cosV * (T(1) - alpha2) + alpha2);
    return T(0.5) / (lambdaL + lambdaV);
}

// The Schlick weight (1 - v . h)^5: F = F0 + (1 - F0) w = F0 (1 - w) + w.
template <class T>
T schlickWeight(T cosVH) {
    const T m = T(1) - cosVH, m2 = m * m;
    return m2 * m2 * m;
}

}  // namespace shadowlab
