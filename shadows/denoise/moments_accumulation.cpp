#include "shadows/denoise/moments_accumulation.h"

#include <vector>

namespace shadowlab {

void accumulateMoments(std::span<const float> v, const GBuffer& g, const Reprojection* reprojection,
                       const MomentsHistory& before, const MomentsSettings& s, MomentsHistory& after,
                       AccumulationBuffers* buffers) {
    const AccumulationSettings signal{.maxFrames = s.historyFrames, .clamp = s.clamp, .varianceGamma = s.varianceGamma};
    const AccumulationSettings moments{.maxFrames = s.historyFrames, .clamp = HistoryClamp::Off};
    std::vector<float> squares(v.size());
    for (size_t k = 0; k < v.size(); ++k) squares[k] = v[k] * v[k];
    accumulate(v, g, reprojection, before.signal, signal, after.signal, buffers);
    accumulate(v, g, reprojection, before.moment1, moments, after.moment1);
    accumulate(squares, g, reprojection, before.moment2, moments, after.moment2);
}

}  // namespace shadowlab
