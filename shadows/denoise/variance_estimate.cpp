#include "shadows/denoise/variance_estimate.h"

#include <algorithm>

#include <tbb/parallel_for.h>

namespace shadowlab {
namespace {

// The moments of V over the neighbourhood's pixels on p's surface, weighted by eqs. 3 and 4.
float spatialVariance(std::span<const float> v, const GBuffer& g, const SurfaceFeatures& f, int i, int j,
                      const EdgeStopping& e, int radius) {
    const size_t p = g.index(i, j);
    float sum = 0.0f, m1 = 0.0f, m2 = 0.0f;
    for (int y = std::max(j - radius, 0); y <= std::min(j + radius, g.height - 1); ++y) {
        for (int x = std::max(i - radius, 0); x <= std::min(i + radius, g.width - 1); ++x) {
            const size_t q = g.index(x, y);
            if (!g.hit[q]) continue;
            const glm::vec2 offset(float(x - i), float(y - j));
            const float w = depthWeight(f.depth[p], f.depth[q], f.depthGradient[p], offset, e.sigmaDepth) *
                            normalWeight(g.shadingNormal[p], g.shadingNormal[q], e.sigmaNormal);
            sum += w, m1 += w * v[q], m2 += w * v[q] * v[q];
        }
    }
    m1 /= sum, m2 /= sum;   // p itself weighs 1: sum >= 1
    return std::max(0.0f, m2 - m1 * m1);
}

}  // namespace

std::vector<float> estimateVariance(std::span<const float> v, const GBuffer& g, const SurfaceFeatures& f,
                                    const MomentsHistory& m, const EdgeStopping& e, const VarianceSettings& s) {
    std::vector<float> variance(g.pixelCount(), 0.0f);
    tbb::parallel_for(0, g.height, [&](int j) {
        for (int i = 0; i < g.width; ++i) {
            const size_t k = g.index(i, j);
            if (!g.hit[k]) continue;
            variance[k] = m.moment1.frames[k] >= float(s.minFrames)
                              ? std::max(0.0f, m.moment2.value[k] - m.moment1.value[k] * m.moment1.value[k])
                              : spatialVariance(v, g, f, i, j, e, s.spatialRadius);
        }
    });
    return variance;
}

}  // namespace shadowlab
