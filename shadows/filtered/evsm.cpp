// The `evsm` moments: exponential variance shadow maps (Lauritzen and McCool 2008,
// "Layered Variance Shadow Maps", section 4). Depth is moved to w = 2 z - 1 in [-1, 1] and
// warped both ways; a texel stores (e^{c+ w}, e^{2 c+ w}, -e^{-c- w}, e^{-2 c- w}), and a
// receiver reads Chebyshev's bound (chebyshev.h) on the positive and on the negative warp:
// the smaller bound wins.
#include <algorithm>
#include <cmath>
#include <vector>

#include "raster/portable_exp.h"
#include "raster/portable_math.h"
#include "shadows/filtered/chebyshev.h"
#include "shadows/filtered/moments.h"

namespace shadowlab {
namespace {

// c+, c- <= 170 keep the moments' dynamic range e^{4 c} (e^680 at most) finite in double
// (the largest double is about e^709).
const SettingsTable<MomentSettings>& exponentialVarianceSettings() {
    using S = MomentSettings;
    static const auto table =
        SettingsTable<S>()
            .real("positive-exponent", member(&S::positiveExponent), 0.1, 170.0, "c+ of e^{c+ (2z - 1)}")
            .real("negative-exponent", member(&S::negativeExponent), 0.1, 170.0, "c- of -e^{-c- (2z - 1)}");
    return table;
}

constexpr size_t kWarpChunk = 256;   // depths warped together, on the stack

// Both warps of count <= kWarpChunk depths, e^{c+ w} into positive and -e^{-c- w} into
// negative, the exponentials a vector at a time.
void warps(const MomentSettings& s, const double* z, size_t count, double* positive, double* negative,
           raster::SimdLevel simd) {
    for (size_t k = 0; k < count; ++k) {
        const double w = 2.0 * z[k] - 1.0;
        positive[k] = s.positiveExponent * w, negative[k] = -s.negativeExponent * w;
    }
    portable::expRun(simd, positive, positive, count);
    portable::expRun(simd, negative, negative, count);
    for (size_t k = 0; k < count; ++k) negative[k] = -negative[k];
}

// perDepth(k, positive, negative) for each of count depths, warped kWarpChunk at a time.
template <class PerDepth>
void forEachWarped(const MomentSettings& s, const double* z, size_t count, raster::SimdLevel simd, PerDepth perDepth) {
    double positive[kWarpChunk], negative[kWarpChunk];
    for (size_t first = 0; first < count; first += kWarpChunk) {
        const size_t n = std::min(kWarpChunk, count - first);
        warps(s, z + first, n, positive, negative, simd);
        for (size_t k = 0; k < n; ++k) perDepth(first + k, positive[k], negative[k]);
    }
}

// The minimum variance carried through a warp: var_w = (dw/dz)^2 var_z at the receiver.
double warpedMinVariance(double exponentTimesTwo, double warped) {
    const double slope = exponentTimesTwo * warped;
    return slope * slope * kMinVariance;
}

void exponentialVarianceMoments(const MomentSettings& s, const double* z, size_t count, double* out,
                                raster::SimdLevel simd) {
    forEachWarped(s, z, count, simd, [&](size_t k, double pos, double neg) {
        double* m = out + 4 * k;
        m[0] = pos, m[1] = pos * pos, m[2] = neg, m[3] = neg * neg;
    });
}

void exponentialVarianceVisibility(const MomentSettings& s, const double* m, const double* t, size_t count, double* out,
                                   raster::SimdLevel simd) {
    forEachWarped(s, t, count, simd, [&](size_t k, double pos, double neg) {
        const double* mk = m + 4 * k;
        const double positive = chebyshevUpperBound(mk[0], mk[1], pos, warpedMinVariance(2.0 * s.positiveExponent, pos));
        const double negative = chebyshevUpperBound(mk[2], mk[3], neg, warpedMinVariance(2.0 * s.negativeExponent, neg));
        out[k] = std::min(positive, negative);
    });
}

// The second moments over w in [-1, 1].
double exponentialVarianceRange(const MomentSettings& s) {
    return portable::exp(4.0 * std::max(s.positiveExponent, s.negativeExponent));
}

}  // namespace

const MomentModel kExponentialVarianceMoments = {
    "evsm", "exponential variance shadow map (Lauritzen and McCool 2008): positive and negative warps", 4,
    exponentialVarianceSettings, exponentialVarianceMoments, exponentialVarianceVisibility,
    exponentialVarianceRange};

}  // namespace shadowlab
