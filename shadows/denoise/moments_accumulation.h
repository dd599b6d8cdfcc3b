// Temporal accumulation of the signal and its first two moments (Schied et al. 2017, SVGF,
// section 4.1): V, and V and V^2 apart, each reprojected and blended by the temporal
// family's accumulation (shadows/temporal/accumulation.h) at max(alpha, 1 / n), alpha =
// 1 / historyFrames. The moments give the variance over time (section 4.2); the signal's
// history may be a filtered one (SVGF feeds back its first wavelet pass) and may be
// clamped to the neighbourhood (AMD's shadow denoiser), the moments never are.
#pragma once

#include <span>

#include "shading/gbuffer.h"
#include "shadows/temporal/accumulation.h"
#include "shadows/temporal/reprojection.h"

namespace shadowlab {

struct MomentsHistory {
    AccumulatedFrame signal;    // V over time; its `frames` is the history's length
    AccumulatedFrame moment1;   // mean of V over time
    AccumulatedFrame moment2;   // mean of V^2 over time
};

struct MomentsSettings {
    int historyFrames = 5;                  // 1 / alpha: SVGF's alpha = 0.2
    HistoryClamp clamp = HistoryClamp::Off; // the signal's history only
    float varianceGamma = 1.0f;
};

// Blends this frame's `visibility` into the history `before` (whose signal the caller may
// have replaced by a filtered one), writing `after`; `buffers` as accumulate() fills them.
void accumulateMoments(std::span<const float> visibility, const GBuffer& gbuffer, const Reprojection* reprojection,
                       const MomentsHistory& before, const MomentsSettings& settings, MomentsHistory& after,
                       AccumulationBuffers* buffers = nullptr);

}  // namespace shadowlab
