// What a filtered shadow map stores per texel, and how a receiver reads visibility back
// from the filtered values (Real-Time Rendering, 4th ed., section 7.7). Every kind maps
// the normalised linear depth z in [0, 1] (soft_shadow_map.h) to a few numbers whose
// filtered (weighted mean) values summarise the depth distribution under the filter. Each
// kind lives in the file named after its technique:
//
//   vsm.cpp   variance: (z, z^2) and Chebyshev's bound (Donnelly and Lauritzen 2006);
//   esm.cpp   exponential: e^{c z} (Annen et al. 2008);
//   evsm.cpp  exponential variance: Chebyshev's bound on a positive and a negative
//             exponential warp (Lauritzen and McCool 2008);
//   msm.cpp   moment shadow maps: (z, z^2, z^3, z^4) and the Hamburger reconstruction
//             (Peters and Klein 2015).
//
// Every value is double, so the classic float-range limits on the exponents (c <= 42 for
// fp32 EVSM) are not what bounds them here; the summed-area table's cancellation is
// (moment_filter.h).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "raster/tile_kernels.h"
#include "shadows/settings_table.h"

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

const char* momentKindName(MomentKind kind);          // "vsm", "esm", "evsm", "msm"
const char* momentKindDescription(MomentKind kind);   // the technique's, for `shadowlab techniques`
int momentCount(MomentKind kind);

// The kind's own parameters, which the family's table includes; `kind` is no parameter.
const SettingsTable<MomentSettings>& momentSettingsTable(MomentKind kind);

// The moments of depth z, written to out[0 .. momentCount - 1].
void momentsOf(const MomentSettings& s, double z, double* out);
// The same for count depths, out holding momentCount values per depth; the exponential
// kinds take their exponentials a vector at a time (raster/portable_exp.h), with the bits
// of momentsOf at every SIMD level.
void momentsOfRun(const MomentSettings& s, const double* z, size_t count, double* out, raster::SimdLevel simd);

// The lit fraction in [0, 1] of a receiver at depth t under the filtered moments.
double momentVisibility(const MomentSettings& s, const double* filtered, double t);
// The same for count receivers, filtered holding momentCount values per receiver.
void momentVisibilityRun(const MomentSettings& s, const double* filtered, const double* t, size_t count, double* out,
                         raster::SimdLevel simd);

// The largest |moment| over z in [0, 1] divided by the smallest value a visibility
// resolves against it (the dynamic range the summed-area table must hold, moment_filter.h).
double momentDynamicRange(const MomentSettings& s);

// One kind of moments, as the file named after its technique defines it; the functions
// above dispatch to it, once per run of texels or receivers (never per value in a pass).
struct MomentModel {
    const char* technique;
    const char* description;
    int count;   // moments per texel, at most kMaxMoments
    const SettingsTable<MomentSettings>& (*settings)();
    void (*moments)(const MomentSettings& s, const double* z, size_t count, double* out, raster::SimdLevel simd);
    void (*visibility)(const MomentSettings& s, const double* filtered, const double* t, size_t count, double* out,
                       raster::SimdLevel simd);
    double (*dynamicRange)(const MomentSettings& s);
};

extern const MomentModel kVarianceMoments;              // vsm.cpp
extern const MomentModel kExponentialMoments;           // esm.cpp
extern const MomentModel kExponentialVarianceMoments;   // evsm.cpp
extern const MomentModel kHamburgerMoments;             // msm.cpp

}  // namespace shadowlab
