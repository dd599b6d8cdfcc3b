#include "shadows/temporal/accumulation.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <tbb/parallel_for.h>

namespace shadowlab {
namespace {

// The range this frame's 3x3 neighbourhood of hit pixels allows the history (accumulation.h).
struct HistoryRange {
    float low, high;
};

HistoryRange neighbourhoodRange(std::span<const float> current, const GBuffer& g, int i, int j,
                         const AccumulationSettings& s) {
    float low = 1e30f, high = -1e30f;
    double sum = 0.0, squares = 0.0;
    int count = 0;
    for (int y = std::max(j - 1, 0); y <= std::min(j + 1, g.height - 1); ++y) {
        for (int x = std::max(i - 1, 0); x <= std::min(i + 1, g.width - 1); ++x) {
            const size_t k = g.index(x, y);
            if (!g.hit[k]) continue;
            const float v = current[k];
            low = std::min(low, v), high = std::max(high, v);
            sum += v, squares += double(v) * v;
            ++count;
        }
    }
    if (s.clamp == HistoryClamp::MinMax) return {low, high};
    const double mean = sum / count;
    const double sigma = std::sqrt(std::max(0.0, squares / count - mean * mean));
    // The box widened to hold the pixel's own value: one that left it out (a hard edge's
    // pixel among the other side's) would pull a history that equals it, and never changes,
    // off towards the neighbours' mean.
    const float own = current[g.index(i, j)];
    return {std::min(own, float(mean - s.varianceGamma * sigma)), std::max(own, float(mean + s.varianceGamma * sigma))};
}

}  // namespace

void accumulate(std::span<const float> current, const GBuffer& g, const Reprojection* reprojection,
                const AccumulatedFrame& before, const AccumulationSettings& s, AccumulatedFrame& after,
                AccumulationBuffers* buffers) {
    if (s.maxFrames < 1 || s.maxFrames > 65535 || !(s.varianceGamma > 0.0f))
        throw std::invalid_argument("temporal accumulation: the frame cap must be in 1..65535 and gamma > 0");
    const size_t n = g.pixelCount();
    if (current.size() != n) throw std::invalid_argument("temporal accumulation: values not of the G-buffer's size");
    if (reprojection) {
        requireHistoryOf(*reprojection, before.value.size(), "temporal accumulation");
        requireHistoryOf(*reprojection, before.frames.size(), "temporal accumulation");
    }
    after.width = g.width, after.height = g.height;
    after.value.assign(n, 0.0f);
    after.frames.assign(n, 0.0f);
    if (buffers) buffers->reprojected.assign(n, 0.0f), buffers->clamped.assign(n, 0.0f);
    const float cap = float(s.maxFrames);
    tbb::parallel_for(0, g.height, [&](int j) {
        for (int i = 0; i < g.width; ++i) {
            const size_t k = g.index(i, j);
            if (!g.hit[k]) continue;
            if (!reprojection || !reprojection->kept[k]) {   // afresh
                after.value[k] = current[k];
                after.frames[k] = 1.0f;
                continue;
            }
            const float reprojected = reprojection->resample(before.value, k);
            float history = reprojected;
            if (s.clamp != HistoryClamp::Off) {
                const HistoryRange range = neighbourhoodRange(current, g, i, j, s);
                history = std::clamp(history, range.low, range.high);
            }
            // n: the frames the history holds, plus this one, capped; blended at 1 / n.
            const float frames = std::min(reprojection->resample(before.frames, k) + 1.0f, cap);
            after.value[k] = history + (current[k] - history) / frames;
            after.frames[k] = frames;
            if (buffers) buffers->reprojected[k] = reprojected, buffers->clamped[k] = history;
        }
    });
}

}  // namespace shadowlab
