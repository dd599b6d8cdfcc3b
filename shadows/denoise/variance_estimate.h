// The variance of V per pixel (Schied et al. 2017, SVGF, section 4.2): from the temporal
// moments, mu2 - mu1^2, where the history holds at least `minFrames` frames; where it is
// shorter (a sequence's first frames, a disocclusion) the moments are estimated over a
// 7x7 neighbourhood instead, weighted by the depth and normal edge-stopping functions
// (eqs. 3, 4), so that a pixel starts with a variance of the surface it lies on.
#pragma once

#include <span>
#include <vector>

#include "shading/gbuffer.h"
#include "shadows/denoise/edge_stopping.h"
#include "shadows/denoise/moments_accumulation.h"
#include "shadows/denoise/surface_features.h"

namespace shadowlab {

struct VarianceSettings {
    int minFrames = 4;    // the paper's: fewer frames of history, the spatial estimate
    int spatialRadius = 3;   // 7x7
};

// Per pixel of the G-buffer (0 where hit = 0); `visibility` is this frame's V.
std::vector<float> estimateVariance(std::span<const float> visibility, const GBuffer& gbuffer,
                                    const SurfaceFeatures& features, const MomentsHistory& moments,
                                    const EdgeStopping& edges, const VarianceSettings& settings);

}  // namespace shadowlab
