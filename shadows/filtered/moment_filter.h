// Filtering a moment map (Real-Time Rendering, 4th ed., section 7.7: "these maps can be
// blurred, mipmapped, put in summed area tables"): the stage between drawing the moments
// and reading visibility back.
//
//   blur   separable box or Gaussian weights, a row pass then a column pass, each output
//          texel the weighted sum of its taps in tap order (never a running sum, whose
//          subtraction would cancel the small exponential moments). Taps past the border
//          read the border texel. Fixed width.
//   sat    a summed-area table (Crow 1984; Lauritzen, GPU Gems 3 ch. 8, "Summed-Area
//          Variance Shadow Maps"): S(X, Y) = the sum of texels x < X, y < Y, so any
//          axis-aligned box, of any width per pixel, is four lookups. Corners between grid
//          points interpolate S bilinearly, which is exactly the integral of the texels
//          (piecewise constant) over the continuous box.
//
// Determinism: rows (then columns) run in parallel, each summed by one task in a fixed
// order; nothing is reduced across threads.
//
// Precision of the table (double, u = 2^-53): each prefix is a compensated (Neumaier)
// running sum, so every S is within 3 u T of the exact sum, T the sum of |moment| over the
// whole map; a box's four-corner combination adds 3 u T more, and its mean over A texels
// is within kSatErrorUlps u T / A of the exact mean, T <= N max|m| for N texels. For moments
// in [0, 1] at 1024^2 texels that is below 2^-29 / A, far under the smallest variance a
// Chebyshev bound uses (1e-7, chebyshev.h). For the exponential kinds V divides the mean
// by e^{c t}, so the error relative to V is that bound times the dynamic range of the
// moments (momentDynamicRange); satRelativeError() evaluates it and the techniques refuse a
// table that cannot resolve V to 2^-10.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "shadows/filtered/moments.h"
#include "shadows/filtered/soft_shadow_map.h"

namespace shadowlab {

// 16 u T covers 3 u T per corner times four corners plus the combination's own rounding.
inline constexpr double kSatErrorUlps = 16.0;

struct MomentMap {
    int size = 0;                   // texels per side
    int channels = 0;               // moments per texel
    // (y size + x) channels + c, row 0 at the top; fresh storage is left uninitialised,
    // since every stage writes each value before anything reads it.
    raster::BufferStorage<double> values;
    const double* at(int x, int y) const;   // clamped to the border
};

enum class BlurKind { Box, Gaussian };
inline constexpr size_t kMaxBlurTaps = 255;   // the widest blur (filter-width's range)

struct SummedAreaTable {
    int size = 0, channels = 0;
    raster::BufferStorage<double> sums;   // (size + 1)^2 entries of `channels`: S(X, Y) at (Y (size + 1) + X)
};

// The kind's moments of every texel's normalised linear depth (the same bits at every SIMD
// level and thread count), in `memory`'s storage (a map kept between frames,
// technique_history.h; reallocated only to grow).
MomentMap momentMap(const SoftShadowMap& soft, const MomentSettings& settings, raster::SimdLevel simd,
                    MomentMap memory = {});

// Weights of an odd `width` (at most kMaxBlurTaps) of taps: equal (box) or Gaussian with
// sigma = width / 6, so the taps span +-3 sigma; normalised to sum 1.
std::vector<double> blurWeights(BlurKind kind, int width);
MomentMap blurMoments(const MomentMap& moments, const std::vector<double>& weights);
// The same into `out`, through `rows` (the row pass's result), both in their own memory:
// a technique keeps them between frames (technique_history.h) and allocates neither again.
void blurMoments(const MomentMap& moments, const std::vector<double>& weights, MomentMap& rows, MomentMap& out);

// The moments at a continuous texel position, bilinear between texel centres.
void sampleBilinear(const MomentMap& moments, const glm::dvec2& texel, double* out);
// The same for count texels, out holding `channels` values per texel.
void sampleBilinearRun(const MomentMap& moments, const glm::dvec2* texels, size_t count, double* out);

// The table of `moments`, in `memory`'s storage (a kept table, as momentMap's).
SummedAreaTable summedAreaTable(const MomentMap& moments, SummedAreaTable memory = {});
// The mean of the moments over the box [lo, hi] (texel units), clipped to the map; a box
// thinner than a texel is widened to one texel about its centre.
void boxMean(const SummedAreaTable& table, glm::dvec2 lo, glm::dvec2 hi, double* out);

// The bound above on a summed-area table's error relative to V for a one-texel box.
double satRelativeError(const MomentSettings& settings, const MomentMap& moments);

}  // namespace shadowlab
