#include "shadows/denoise/atrous_pass.h"

#include <algorithm>

#include <tbb/parallel_for.h>

namespace shadowlab {
namespace {

constexpr float kSpline[5] = {1.0f / 16.0f, 1.0f / 4.0f, 3.0f / 8.0f, 1.0f / 4.0f, 1.0f / 16.0f};   // B3 spline
constexpr float kGauss3[3] = {0.25f, 0.5f, 0.25f};

// p's variance under a 3x3 Gaussian over the hit pixels (section 4.3).
float blurredVariance(const std::vector<float>& variance, const GBuffer& g, int i, int j) {
    float sum = 0.0f, weights = 0.0f;
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            const int x = i + dx, y = j + dy;
            if (x < 0 || y < 0 || x >= g.width || y >= g.height || !g.hit[g.index(x, y)]) continue;
            const float h = kGauss3[dx + 1] * kGauss3[dy + 1];
            sum += h * variance[g.index(x, y)], weights += h;
        }
    }
    return sum / weights;
}

void filterAtStep(const FilteredSignal& in, const GBuffer& g, const SurfaceFeatures& f, const EdgeStopping& e,
                 int step, int i, int j, FilteredSignal& out) {
    const size_t p = g.index(i, j);
    const float variance = blurredVariance(in.variance, g, i, j);
    float weights = 0.0f, value = 0.0f, carried = 0.0f;
    for (int b = 0; b < 5; ++b) {
        for (int a = 0; a < 5; ++a) {
            const int x = i + (a - 2) * step, y = j + (b - 2) * step;
            if (x < 0 || y < 0 || x >= g.width || y >= g.height) continue;
            const size_t q = g.index(x, y);
            if (!g.hit[q]) continue;
            const glm::vec2 offset(float(x - i), float(y - j));
            const float w = depthWeight(f.depth[p], f.depth[q], f.depthGradient[p], offset, e.sigmaDepth) *
                            normalWeight(g.shadingNormal[p], g.shadingNormal[q], e.sigmaNormal) *
                            signalWeight(in.value[p], in.value[q], variance, e.sigmaLuminance);
            const float hw = kSpline[a] * kSpline[b] * w;
            weights += hw, value += hw * in.value[q], carried += hw * hw * in.variance[q];
        }
    }
    // p itself weighs (3/8)^2 > 0: the sums never vanish.
    out.value[p] = value / weights;
    out.variance[p] = carried / (weights * weights);
}

}  // namespace

void atrousPass(const FilteredSignal& in, const GBuffer& g, const SurfaceFeatures& f, const EdgeStopping& e,
                int step, std::span<const uint8_t> filtered, FilteredSignal& out) {
    out.value = in.value;
    out.variance = in.variance;
    tbb::parallel_for(0, g.height, [&](int j) {
        for (int i = 0; i < g.width; ++i) {
            const size_t k = g.index(i, j);
            if (g.hit[k] && (filtered.empty() || filtered[k])) filterAtStep(in, g, f, e, step, i, j, out);
        }
    });
}

}  // namespace shadowlab
