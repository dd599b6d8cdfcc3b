// The penumbra-driven shadow denoiser, after the inputs NVIDIA NRD's SIGMA documents (its
// README: the hit distance and the tangent of the light's angular radius; docs/
// denoisers.md): the kernel's radius per pixel from the penumbra's width on the screen
// (penumbra_radius.h), a spatial filter of that radius (penumbra_filter.h), then temporal
// stabilisation: the filtered V accumulated over frames with its history clamped to the
// neighbourhood (shadows/temporal/accumulation.h), as SIGMA's optional stabilisation pass.
// Where the penumbra estimate is 0 (a point light, a hard edge) nothing is blurred.
#pragma once

#include <vector>

#include "shadows/debug_buffers.h"
#include "shadows/denoise/denoise_inputs.h"
#include "shadows/denoise/edge_stopping.h"
#include "shadows/denoise/penumbra_radius.h"
#include "shadows/temporal/accumulation.h"

namespace shadowlab {

struct PenumbraSettings {
    PenumbraRadiusSettings radius;
    EdgeStopping edges;
    int taps = 32;
    AccumulationSettings stabilisation{.maxFrames = 8, .clamp = HistoryClamp::Variance, .varianceGamma = 1.5f};
};

// This frame's denoised V, `after` the stabilised history (from `before`, reprojected by
// in.reprojection). `debug` gets penumbra-radius (pixels), penumbra-spatial and
// penumbra-frames. Throws std::invalid_argument for inputs not of the G-buffer's size or
// settings the stages refuse.
std::vector<float> denoisePenumbra(const DenoiseInputs& in, const PenumbraSettings& settings,
                                   const AccumulatedFrame& before, AccumulatedFrame& after,
                                   const DebugBuffers* debug = nullptr);

}  // namespace shadowlab
