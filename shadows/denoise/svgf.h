// SVGF, spatiotemporal variance-guided filtering (Schied et al. 2017, HPG), for a shadow's
// V (docs/denoisers.md): V and its moments accumulated over time (section 4.1,
// moments_accumulation.h), the variance estimated from them or, for a short history, over
// space (section 4.2, variance_estimate.h), then `passes` à-trous wavelet passes whose
// edge-stopping on V is scaled by the variance they carry along (section 4.3,
// atrous_pass.h). The output of pass `feedbackPass` becomes the signal's history for the
// next frame, as the paper's first pass does: smoothed enough to steady the history,
// not so much that detail is lost for good.
#pragma once

#include <vector>

#include "shadows/debug_buffers.h"
#include "shadows/denoise/denoise_inputs.h"
#include "shadows/denoise/edge_stopping.h"
#include "shadows/denoise/moments_accumulation.h"
#include "shadows/denoise/variance_estimate.h"

namespace shadowlab {

struct SvgfSettings {
    MomentsSettings moments;     // alpha = 0.2, no clamp: the paper's
    VarianceSettings variance;
    EdgeStopping edges;
    int passes = 5;              // the paper's five, steps 1 to 16
    int feedbackPass = 1;        // 1..passes
};

// This frame's denoised V (the input's V where hit = 0), `after` the history for the next
// frame (from `before`, reprojected by in.reprojection). `debug`, if enabled, gets
// svgf-accumulated, svgf-variance, svgf-pass-<i> (V) and svgf-pass-<i>-variance. Throws
// std::invalid_argument for passes outside 1..10, feedbackPass outside 1..passes, or inputs
// not of the G-buffer's size.
std::vector<float> denoiseSvgf(const DenoiseInputs& in, const SvgfSettings& settings, const MomentsHistory& before,
                               MomentsHistory& after, const DebugBuffers* debug = nullptr);

}  // namespace shadowlab
