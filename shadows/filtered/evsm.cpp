// The `evsm` moments: exponential variance shadow maps (Lauritzen and McCool 2008,
// "Layered Variance Shadow Maps", section 4). Depth is moved to w = 2 z - 1 in [-1, 1] and
// warped both ways; a texel stores (e^{c+ w}, e^{2 c+ w}, -e^{-c- w}, e^{-2 c- w}), and a
// receiver reads Chebyshev's bound (chebyshev.h) on the positive and on the negative warp:
// the smaller bound wins.
#include <algorithm>
#include <cmath>

#include "raster/portable_math.h"
#include "shadows/filtered/chebyshev.h"
#include "shadows/filtered/moments.h"

namespace shadowlab {
namespace {

// c+, c- <= 170 keep the moments' dynamic range e^{4 c} (e^680 at most) finite in double
// (the largest double is about e^709).
std::vector<ParamSpec> exponentialVarianceParams() {
    return {realParam("positive-exponent", 40.0, 0.1, 170.0, "c+ of e^{c+ (2z - 1)}"),
            realParam("negative-exponent", 5.0, 0.1, 170.0, "c- of -e^{-c- (2z - 1)}")};
}

void readExponentialVariance(const TechniqueParams& p, MomentSettings& s) {
    s.positiveExponent = p.real("positive-exponent");
    s.negativeExponent = p.real("negative-exponent");
}

double positiveWarp(const MomentSettings& s, double z) { return portable::exp(s.positiveExponent * (2.0 * z - 1.0)); }
double negativeWarp(const MomentSettings& s, double z) { return -portable::exp(-s.negativeExponent * (2.0 * z - 1.0)); }

// The minimum variance carried through a warp: var_w = (dw/dz)^2 var_z at the receiver.
double warpedMinVariance(double exponentTimesTwo, double warped) {
    const double slope = exponentTimesTwo * warped;
    return slope * slope * kMinVariance;
}

void exponentialVarianceMoments(const MomentSettings& s, double z, double* out) {
    const double pos = positiveWarp(s, z), neg = negativeWarp(s, z);
    out[0] = pos, out[1] = pos * pos, out[2] = neg, out[3] = neg * neg;
}

double exponentialVarianceVisibility(const MomentSettings& s, const double* m, double t) {
    const double pos = positiveWarp(s, t), neg = negativeWarp(s, t);
    const double positive = chebyshevUpperBound(m[0], m[1], pos, warpedMinVariance(2.0 * s.positiveExponent, pos));
    const double negative = chebyshevUpperBound(m[2], m[3], neg, warpedMinVariance(2.0 * s.negativeExponent, neg));
    return std::min(positive, negative);
}

// The second moments over w in [-1, 1].
double exponentialVarianceRange(const MomentSettings& s) {
    return portable::exp(4.0 * std::max(s.positiveExponent, s.negativeExponent));
}

}  // namespace

const MomentModel kExponentialVarianceMoments = {
    "evsm", "exponential variance shadow map (Lauritzen and McCool 2008): positive and negative warps", 4,
    exponentialVarianceParams, readExponentialVariance, exponentialVarianceMoments, exponentialVarianceVisibility,
    exponentialVarianceRange};

}  // namespace shadowlab
