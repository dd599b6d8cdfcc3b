// The ray-traced technique's denoising (docs/denoisers.md): its noisy V and occluder distance
// (shadow_rays.h) handed to one of the denoisers of shadows/denoise/, with the frame's
// reprojection and the denoiser's history kept between frames.
#pragma once

#include <optional>
#include <vector>

#include "shadows/denoise/moments_accumulation.h"
#include "shadows/denoise/denoise_inputs.h"
#include "shadows/raytraced/shadow_rays.h"
#include "shadows/technique.h"

namespace shadowlab {

enum class ShadowDenoiser { None, Svgf, Tiled, Penumbra };

// What the denoisers keep from frame to frame (technique_history.h): the last frame's and
// the one being written, swapped after each frame.
struct DenoiserHistory {
    MomentsHistory moments, nextMoments;            // svgf, tiled
    AccumulatedFrame stabilised, nextStabilised;    // penumbra
};

// The light's size as the penumbra estimate reads it: a disk's radius, a rectangle as the
// disk of its area, a sun's tangent of half its angular diameter; a point or spot light none.
DenoiseLight denoiseLightOf(const Light& light);

struct DenoisedRays {
    std::vector<float> visibility;
    std::optional<double> skippedTilesShare;   // tiled: the share of tiles left unfiltered
};

// `which` (not None) over this frame's rays, the history reprojected through in.previous
// where the frame has one (and the history is of its size). Debug buffers go to in.debugDir.
DenoisedRays denoiseRays(const ShadowInputs& in, ShadowDenoiser which, const ShadowRayBuffers& rays,
                         DenoiserHistory& history);

}  // namespace shadowlab
