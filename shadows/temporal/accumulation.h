// Temporal accumulation: each pixel's value averaged over the frames its surface has been
// seen in (docs/temporal.md). The history, reprojected (reprojection.h), is blended with
// this frame's value at weight 1 / n, n the frames it holds plus this one, capped: the
// running mean of the first frames, then an exponential average of the last `maxFrames`
// or so (Schied et al. 2017, SVGF, section 4.1: alpha = max(alpha_min, 1 / n); Karis 2014,
// "High Quality Temporal Supersampling"). A still view's pixel so converges to the mean of
// its frames' values, with no ghost of the first frames once n is capped.
//
// Before blending, the history may be clamped to this frame's neighbourhood (Karis 2014;
// Salvi 2016, "An Excursion in Temporal Supersampling", variance clipping): what the 3x3
// pixels around it see now bounds what the pixel may remember, so a shadow that moved away
// does not linger as a ghost, at the price of letting some of this frame's noise through.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "shading/gbuffer.h"
#include "shadows/temporal/reprojection.h"

namespace shadowlab {

enum class HistoryClamp {
    Off,        // the history as reprojected
    MinMax,     // into [min, max] of the 3x3 neighbourhood's values this frame
    Variance,   // into mean +- gamma sigma of the 3x3 neighbourhood (Salvi 2016), widened to hold this frame's own value
};

struct AccumulationSettings {
    int maxFrames = 16;            // the cap on n: 1 keeps no history
    HistoryClamp clamp = HistoryClamp::MinMax;
    float varianceGamma = 1.0f;    // Variance: the box's half-width in standard deviations
};

// A pixel's value over the frames so far, and how many frames it holds (0 where none: a
// background pixel, or a frame without history). Indexed as the frame's G-buffer.
struct AccumulatedFrame {
    int width = 0, height = 0;
    std::vector<float> value;
    std::vector<float> frames;
};

// Per pixel: what the stage did, for the debug buffers and the stats.
struct AccumulationBuffers {
    std::vector<float> reprojected;   // the history resampled here, before clamping; 0 where rejected
    std::vector<float> clamped;       // the history after clamping
};

// Blends `current` (this frame's values, per G-buffer pixel, hit pixels read) into the
// history `before`, reprojected by `reprojection` (null: the frame has none; every pixel
// starts afresh), writing `after` (resized to the G-buffer); `buffers`, if given, gets the
// intermediate values. Throws std::invalid_argument for settings outside maxFrames in
// 1..65535 and varianceGamma > 0, or a `current` that is not the G-buffer's size.
void accumulate(std::span<const float> current, const GBuffer& gbuffer, const Reprojection* reprojection,
                const AccumulatedFrame& before, const AccumulationSettings& settings, AccumulatedFrame& after,
                AccumulationBuffers* buffers = nullptr);

}  // namespace shadowlab
