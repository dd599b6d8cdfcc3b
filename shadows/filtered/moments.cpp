#include "shadows/filtered/moments.h"

#include <algorithm>
#include <cmath>

namespace shadowlab {
namespace {

// The smallest variance Chebyshev's bound uses, in normalised depth units squared
// (Donnelly and Lauritzen 2006, section 3.2: "clamp the variance to a minimum" against
// rounding). 1e-7 is a depth spread of 3e-4 of the light's range, about 4 mm over the
// built-in scenes' 14 m: far below one texel's depth slope on any lit receiver, far above
// the double rounding of M2 - M1^2 (2^-52).
constexpr double kMinVariance = 1e-7;
// Peters and Klein 2015, Algorithm 3: the moment bias alpha that keeps the Hankel matrix
// of the moments positive definite against rounding (their value for 4MSM).
constexpr double kHamburgerMomentBias = 3e-5;

// Chebyshev's one-sided bound (RTR eqs. 7.7 and 7.8): the largest fraction of a
// distribution with mean m1 and second moment m2 that can lie at or beyond t.
double chebyshevUpperBound(double m1, double m2, double t, double minVariance) {
    if (t <= m1) return 1.0;
    const double variance = std::max(m2 - m1 * m1, minVariance);
    const double d = t - m1;
    return variance / (variance + d * d);
}

// Lauritzen's light-bleeding reduction: linstep(amount, 1, p).
double reduceBleeding(double p, double amount) { return std::clamp((p - amount) / (1.0 - amount), 0.0, 1.0); }

// Exponential variance warps of Lauritzen and McCool 2008: depth moved to [-1, 1] first.
double positiveWarp(const MomentSettings& s, double z) { return std::exp(s.positiveExponent * (2.0 * z - 1.0)); }
double negativeWarp(const MomentSettings& s, double z) { return -std::exp(-s.negativeExponent * (2.0 * z - 1.0)); }

// The minimum variance carried through a warp: var_w = (dw/dz)^2 var_z at the receiver.
double warpedMinVariance(double exponentTimesTwo, double warped) {
    const double slope = exponentTimesTwo * warped;
    return slope * slope * kMinVariance;
}

// Peters and Klein 2015, Algorithm 3 ("Hamburger 4MSM"), in double. Returns the shadow
// intensity G: the least fraction of the filtered depths in front of t consistent with
// the (biased) moments b[0..3].
double hamburgerShadowIntensity(const double* moments, double t) {
    double b[4];
    for (int k = 0; k < 4; ++k) b[k] = (1.0 - kHamburgerMomentBias) * moments[k] + kHamburgerMomentBias * 0.5;
    // Solve the Hankel system [1 b0 b1; b0 b1 b2; b1 b2 b3] c = (1, t, t^2) by its
    // Cholesky (L D L^T) factorisation: L21 = b0, L31 = b1, D1 = 1.
    const double d2 = b[1] - b[0] * b[0];
    const double l32 = (b[2] - b[0] * b[1]) / d2;
    const double d3 = b[3] - b[1] * b[1] - l32 * l32 * d2;
    double c1 = 1.0, c2 = t - b[0], c3 = t * t - b[1] - l32 * c2;   // forward substitution
    c2 /= d2, c3 /= d3;                                               // diagonal
    c2 -= l32 * c3, c1 -= b[0] * c2 + b[1] * c3;                      // back substitution
    // The roots z2 <= z3 of c3 z^2 + c2 z + c1 = 0 are the other two support points.
    const double p = c2 / c3, q = c1 / c3;
    const double r = std::sqrt(std::max(0.25 * p * p - q, 0.0));
    const double z2 = -0.5 * p - r, z3 = -0.5 * p + r;
    if (t <= z2) return 0.0;
    if (t <= z3) return (t * z3 - b[0] * (t + z3) + b[1]) / ((z3 - z2) * (t - z2));
    return 1.0 - (z2 * z3 - b[0] * (z2 + z3) + b[1]) / ((t - z2) * (t - z3));
}

}  // namespace

const char* momentKindName(MomentKind kind) {
    switch (kind) {
        case MomentKind::Variance: return "vsm";
        case MomentKind::Exponential: return "esm";
        case MomentKind::ExponentialVariance: return "evsm";
        case MomentKind::Hamburger4: return "msm";
    }
    return "";
}

int momentCount(MomentKind kind) {
    switch (kind) {
        case MomentKind::Variance: return 2;
        case MomentKind::Exponential: return 1;
        case MomentKind::ExponentialVariance: return 4;
        case MomentKind::Hamburger4: return 4;
    }
    return 0;
}

// The exponents' bounds keep every moment finite in double: e^{2 * 170 * 2} overflows,
// e^680 does not (largest double ~ e^709).
std::vector<ParamSpec> momentParamSpecs(MomentKind kind) {
    switch (kind) {
        case MomentKind::Variance:
            return {realParam("bleeding-reduction", 0.2, 0.0, 0.99,
                              "Chebyshev bounds below this are shadow, the rest stretched to [0, 1]")};
        case MomentKind::Exponential:
            return {realParam("exponent", 80.0, 0.1, 700.0, "c of e^{c z}, z the normalised linear depth")};
        case MomentKind::ExponentialVariance:
            return {realParam("positive-exponent", 40.0, 0.1, 170.0, "c+ of e^{c+ (2z - 1)}"),
                    realParam("negative-exponent", 5.0, 0.1, 170.0, "c- of -e^{-c- (2z - 1)}")};
        case MomentKind::Hamburger4: return {};
    }
    return {};
}

MomentSettings readMomentSettings(MomentKind kind, const TechniqueParams& p) {
    MomentSettings s;
    s.kind = kind;
    if (kind == MomentKind::Variance) s.bleedingReduction = p.real("bleeding-reduction");
    if (kind == MomentKind::Exponential) s.exponent = p.real("exponent");
    if (kind == MomentKind::ExponentialVariance) {
        s.positiveExponent = p.real("positive-exponent");
        s.negativeExponent = p.real("negative-exponent");
    }
    return s;
}

void momentsOf(const MomentSettings& s, double z, double* out) {
    switch (s.kind) {
        case MomentKind::Variance: out[0] = z, out[1] = z * z; return;
        case MomentKind::Exponential: out[0] = std::exp(s.exponent * z); return;
        case MomentKind::ExponentialVariance: {
            const double pos = positiveWarp(s, z), neg = negativeWarp(s, z);
            out[0] = pos, out[1] = pos * pos, out[2] = neg, out[3] = neg * neg;
            return;
        }
        case MomentKind::Hamburger4: out[0] = z, out[1] = z * z, out[2] = z * z * z, out[3] = z * z * z * z; return;
    }
}

double momentVisibility(const MomentSettings& s, const double* m, double t) {
    switch (s.kind) {
        case MomentKind::Variance:
            return reduceBleeding(chebyshevUpperBound(m[0], m[1], t, kMinVariance), s.bleedingReduction);
        case MomentKind::Exponential: return std::clamp(m[0] * std::exp(-s.exponent * t), 0.0, 1.0);
        case MomentKind::ExponentialVariance: {
            const double pos = positiveWarp(s, t), neg = negativeWarp(s, t);
            const double positive = chebyshevUpperBound(m[0], m[1], pos, warpedMinVariance(2.0 * s.positiveExponent, pos));
            const double negative = chebyshevUpperBound(m[2], m[3], neg, warpedMinVariance(2.0 * s.negativeExponent, neg));
            return std::min(positive, negative);
        }
        case MomentKind::Hamburger4: return 1.0 - std::clamp(hamburgerShadowIntensity(m, t), 0.0, 1.0);
    }
    return 0.0;
}

double momentDynamicRange(const MomentSettings& s) {
    switch (s.kind) {
        case MomentKind::Variance:
        case MomentKind::Hamburger4: return 1.0;   // moments in [0, 1], compared absolutely
        case MomentKind::Exponential: return std::exp(s.exponent);   // V = E e^{-c t}, t in [0, 1]
        case MomentKind::ExponentialVariance:   // second moments over w in [-1, 1]
            return std::exp(4.0 * std::max(s.positiveExponent, s.negativeExponent));
    }
    return 1.0;
}

}  // namespace shadowlab
