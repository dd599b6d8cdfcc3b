// The `msm` moments: moment shadow maps (Peters and Klein 2015, "Moment Shadow Mapping",
// Algorithm 3). A texel stores (z, z^2, z^3, z^4); a receiver at depth t reads the Hamburger
// four-moment reconstruction: the moments, biased towards (0.5, 0.5, 0.5, 0.5) by
// alpha = 3e-5 (their value), give the lower bound of the lit fraction over all
// distributions with them.
#include <algorithm>
#include <cmath>

#include "shadows/filtered/moments.h"

namespace shadowlab {
namespace {

// Peters and Klein 2015, Algorithm 3: the moment bias alpha that keeps the Hankel matrix
// of the moments positive definite against rounding (their value for 4MSM).
constexpr double kHamburgerMomentBias = 3e-5;

const SettingsTable<MomentSettings>& hamburgerSettings() {
    static const SettingsTable<MomentSettings> none;   // no parameter of its own
    return none;
}

void hamburgerMoments(const MomentSettings&, const double* z, size_t count, double* out, raster::SimdLevel) {
    for (size_t k = 0; k < count; ++k) {
        double* m = out + 4 * k;
        m[0] = z[k], m[1] = z[k] * z[k], m[2] = z[k] * z[k] * z[k], m[3] = z[k] * z[k] * z[k] * z[k];
    }
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

void hamburgerVisibility(const MomentSettings&, const double* m, const double* t, size_t count, double* out,
                         raster::SimdLevel) {
    for (size_t k = 0; k < count; ++k) out[k] = 1.0 - std::clamp(hamburgerShadowIntensity(m + 4 * k, t[k]), 0.0, 1.0);
}

double hamburgerRange(const MomentSettings&) { return 1.0; }   // moments in [0, 1], compared absolutely

}  // namespace

const MomentModel kHamburgerMoments = {"msm",
                                       "moment shadow map (Peters and Klein 2015): four moments, Hamburger reconstruction",
                                       4, hamburgerSettings, hamburgerMoments, hamburgerVisibility,
                                       hamburgerRange};

}  // namespace shadowlab
