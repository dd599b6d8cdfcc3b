// The `esm` moments: exponential shadow maps (Annen et al. 2008; Real-Time Rendering, 4th
// ed., section 7.7). A texel stores e^{c z}; a receiver at depth t reads
// V = E[e^{c z}] e^{-c t}, clamped to 1 (Annen et al., eq. 4: the step of the depth test
// replaced by an exponential).
#include <algorithm>
#include <cmath>

#include "raster/portable_exp.h"
#include "raster/portable_math.h"
#include "shadows/filtered/moments.h"

namespace shadowlab {
namespace {

// c <= 700 keeps the moment and its dynamic range e^c finite in double (the largest double
// is about e^709).
const SettingsTable<MomentSettings>& exponentialSettings() {
    static const auto table = SettingsTable<MomentSettings>().real(
        "exponent", member(&MomentSettings::exponent), 0.1, 700.0, "c of e^{c z}, z the normalised linear depth");
    return table;
}

// e^{c z}, the exponentials a vector at a time.
void exponentialMoments(const MomentSettings& s, const double* z, size_t count, double* out, raster::SimdLevel simd) {
    for (size_t k = 0; k < count; ++k) out[k] = s.exponent * z[k];
    portable::expRun(simd, out, out, count);
}

// V = E[e^{c z}] e^{-c t}, clamped to 1.
void exponentialVisibility(const MomentSettings& s, const double* m, const double* t, size_t count, double* out,
                           raster::SimdLevel simd) {
    for (size_t k = 0; k < count; ++k) out[k] = -s.exponent * t[k];
    portable::expRun(simd, out, out, count);
    for (size_t k = 0; k < count; ++k) out[k] = std::clamp(m[k] * out[k], 0.0, 1.0);
}

double exponentialRange(const MomentSettings& s) { return portable::exp(s.exponent); }   // V = E e^{-c t}, t in [0, 1]

}  // namespace

const MomentModel kExponentialMoments = {"esm", "exponential shadow map (RTR 7.7, Annen et al. 2008): filtered e^{cz}", 1,
                                         exponentialSettings, exponentialMoments, exponentialVisibility,
                                         exponentialRange};

}  // namespace shadowlab
