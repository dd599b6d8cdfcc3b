// What a filtered shadow map stores per texel, and how a receiver reads visibility back
// from the filtered values (Real-Time Rendering, 4th ed., section 7.7). Every kind maps
// the normalised linear depth z in [0, 1] (soft_shadow_map.h) to a few numbers whose
// filtered (weighted mean) values summarise the depth distribution under the filter:
//
//   variance     (z, z^2); Chebyshev's one-sided bound p_max = s^2 / (s^2 + (t - M1)^2)
//                for t > M1, s^2 = M2 - M1^2 (eqs. 7.7, 7.8; Donnelly and Lauritzen 2006),
//                with a minimum variance and Lauritzen's light-bleeding reduction: p below
//                `amount` counts as shadow, the rest is stretched to [0, 1] (RTR 7.7;
//                Lauritzen, GPU Gems 3 ch. 8).
//   exponential  (e^{c z}); V = E[e^{c z}] e^{-c t}, clamped to 1 (Annen et al. 2008,
//                eq. 4: the step of the depth test replaced by an exponential).
//   exponential  (e^{c+ w}, e^{2 c+ w}, -e^{-c- w}, e^{-2 c- w}) with w = 2 z - 1: Chebyshev
//   variance     on the positive and the negative warp, the smaller bound wins (Lauritzen
//                and McCool 2008, "Layered Variance Shadow Maps", section 4).
//   hamburger4   (z, z^2, z^3, z^4); the Hamburger four-moment reconstruction of Peters
//                and Klein 2015 ("Moment Shadow Mapping", Algorithm 3): the moments, biased
//                towards (0.5, 0.5, 0.5, 0.5) by alpha = 3e-5 (their value), give the
//                lower bound of the lit fraction over all distributions with them.
// Every value is double, so the classic float-range limits on the exponents (c <= 42 for
// fp32 EVSM) are not what bounds them here; the summed-area table's cancellation is
// (moment_filter.h).
#pragma once

#include <string>
#include <vector>

#include "shadows/technique_params.h"

namespace shadowlab {

enum class MomentKind { Variance, Exponential, ExponentialVariance, Hamburger4 };

inline constexpr int kMaxMoments = 4;

struct MomentSettings {
    MomentKind kind = MomentKind::Variance;
    double bleedingReduction = 0.2;   // variance: p below this is shadow (0: off)
    double exponent = 80.0;           // exponential: c
    double positiveExponent = 40.0;   // exponential variance: c+
    double negativeExponent = 5.0;    // exponential variance: c-
};

const char* momentKindName(MomentKind kind);   // "vsm", "esm", "evsm", "msm"
int momentCount(MomentKind kind);

// The kind's own parameters (added to the family's) and their reading.
std::vector<ParamSpec> momentParamSpecs(MomentKind kind);
MomentSettings readMomentSettings(MomentKind kind, const TechniqueParams& params);

// The moments of depth z, written to out[0 .. momentCount - 1].
void momentsOf(const MomentSettings& s, double z, double* out);

// The lit fraction in [0, 1] of a receiver at depth t under the filtered moments.
double momentVisibility(const MomentSettings& s, const double* filtered, double t);

// The largest |moment| over z in [0, 1] divided by the smallest value a visibility
// resolves against it (the dynamic range the summed-area table must hold, moment_filter.h).
double momentDynamicRange(const MomentSettings& s);

}  // namespace shadowlab
