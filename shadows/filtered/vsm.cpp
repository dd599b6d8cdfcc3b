// The `vsm` moments: variance shadow maps (Donnelly and Lauritzen 2006; Real-Time
// Rendering, 4th ed., section 7.7). A texel stores (z, z^2); a receiver at depth t reads
// Chebyshev's one-sided bound p_max = s^2 / (s^2 + (t - M1)^2) for t > M1, s^2 = M2 - M1^2
// (eqs. 7.7, 7.8; chebyshev.h), with a minimum variance and Lauritzen's light-bleeding
// reduction: p below `amount` counts as shadow, the rest is stretched to [0, 1] (RTR 7.7;
// Lauritzen, GPU Gems 3 ch. 8).
#include <algorithm>

#include "shadows/filtered/chebyshev.h"
#include "shadows/filtered/moments.h"

namespace shadowlab {
namespace {

const SettingsTable<MomentSettings>& varianceSettings() {
    static const auto table = SettingsTable<MomentSettings>().real(
        "bleeding-reduction", member(&MomentSettings::bleedingReduction), 0.0, 0.99,
        "Chebyshev bounds below this are shadow, the rest stretched to [0, 1]");
    return table;
}

void varianceMoments(const MomentSettings&, const double* z, size_t count, double* out, raster::SimdLevel) {
    for (size_t k = 0; k < count; ++k) out[2 * k] = z[k], out[2 * k + 1] = z[k] * z[k];
}

// Lauritzen's light-bleeding reduction: linstep(amount, 1, p).
double reduceBleeding(double p, double amount) { return std::clamp((p - amount) / (1.0 - amount), 0.0, 1.0); }

void varianceVisibility(const MomentSettings& s, const double* m, const double* t, size_t count, double* out,
                        raster::SimdLevel) {
    for (size_t k = 0; k < count; ++k) {
        out[k] = reduceBleeding(chebyshevUpperBound(m[2 * k], m[2 * k + 1], t[k], kMinVariance), s.bleedingReduction);
    }
}

double varianceRange(const MomentSettings&) { return 1.0; }   // moments in [0, 1], compared absolutely

}  // namespace

const MomentModel kVarianceMoments = {
    "vsm", "variance shadow map (RTR 7.7, Donnelly and Lauritzen 2006): Chebyshev bound, light-bleeding reduction", 2,
    varianceSettings, varianceMoments, varianceVisibility, varianceRange};

}  // namespace shadowlab
