// The tile-classified shadow denoiser, after AMD FidelityFX Shadow Denoiser's public
// description (GPUOpen, "FidelityFX Denoiser 1.3"; docs/denoisers.md): V reprojected and
// accumulated with its history clamped to this frame's neighbourhood moments, against
// ghosting ("analyzing the local pixel neighborhood and clamping the accumulated
// history"; moments_accumulation.h with HistoryClamp::Variance); 8x8 tiles classified
// (tile_classification.h), and a few edge-aware à-trous passes (atrous_pass.h), guided by
// the variance (variance_estimate.h, whose spatial estimate for a short history is the
// "increased contribution of spatial filters on low temporal sample counts"), run on the
// tiles that need them only. The history is the accumulated, unfiltered V.
#pragma once

#include <vector>

#include "shadows/debug_buffers.h"
#include "shadows/denoise/denoise_inputs.h"
#include "shadows/denoise/edge_stopping.h"
#include "shadows/denoise/moments_accumulation.h"
#include "shadows/denoise/variance_estimate.h"

namespace shadowlab {

struct TiledSettings {
    MomentsSettings moments{.historyFrames = 16, .clamp = HistoryClamp::Variance, .varianceGamma = 1.0f};
    VarianceSettings variance;
    EdgeStopping edges;
    int passes = 3;     // steps 1, 2, 4
    int tileSize = 8;
};

struct TiledResult {
    std::vector<float> visibility;   // denoised; the input's V where hit = 0
    size_t skippedTiles = 0, surfacedTiles = 0;   // tiles left unfiltered, of those with a surface pixel
    double skippedShare() const { return surfacedTiles ? double(skippedTiles) / double(surfacedTiles) : 0.0; }
};

// As denoiseSvgf() (svgf.h); `debug` gets tiled-accumulated, tiled-variance, tiled-classes
// (0 empty, 1 lit, 2 shadowed, 3 filtered) and tiled-pass-<i>. Throws std::invalid_argument
// for passes outside 1..10.
TiledResult denoiseTiled(const DenoiseInputs& in, const TiledSettings& settings, const MomentsHistory& before,
                         MomentsHistory& after, const DebugBuffers* debug = nullptr);

}  // namespace shadowlab
