#include "shadows/denoise/penumbra_filter.h"

#include <array>
#include <cmath>
#include <stdexcept>

#include <tbb/parallel_for.h>

#include "raster/portable_math.h"

namespace shadowlab {
namespace {

// Tap t of n on the unit disk: radius sqrt((t + 0.5) / n), turned by the golden angle.
std::array<glm::vec2, kMaxPenumbraTaps> spiral(int n) {
    constexpr double kGoldenAngle = 2.39996322972865332;   // pi (3 - sqrt 5)
    std::array<glm::vec2, kMaxPenumbraTaps> taps{};
    for (int t = 0; t < n; ++t) {
        const double r = std::sqrt((t + 0.5) / n), a = kGoldenAngle * t;
        taps[size_t(t)] = glm::vec2(float(r * portable::cos(a)), float(r * portable::sin(a)));
    }
    return taps;
}

float filterAtRadius(std::span<const float> v, const GBuffer& g, const SurfaceFeatures& f, float radius,
                  const EdgeStopping& e, const std::array<glm::vec2, kMaxPenumbraTaps>& taps, int n, int i, int j) {
    const size_t p = g.index(i, j);
    float weights = 1.0f, sum = v[p];   // p itself, at weight 1
    for (int t = 0; t < n; ++t) {
        const glm::vec2 offset = taps[size_t(t)] * radius;
        const int x = i + int(std::lround(offset.x)), y = j + int(std::lround(offset.y));
        if (x < 0 || y < 0 || x >= g.width || y >= g.height || (x == i && y == j)) continue;
        const size_t q = g.index(x, y);
        if (!g.hit[q]) continue;
        const glm::vec2 d(float(x - i), float(y - j));
        const float w = float(portable::exp(-2.0f * glm::dot(d, d) / (radius * radius))) *
                        depthWeight(f.depth[p], f.depth[q], f.depthGradient[p], d, e.sigmaDepth) *
                        normalWeight(g.shadingNormal[p], g.shadingNormal[q], e.sigmaNormal);
        weights += w, sum += w * v[q];
    }
    return sum / weights;
}

}  // namespace

std::vector<float> penumbraFilter(std::span<const float> v, const GBuffer& g, const SurfaceFeatures& f,
                                  std::span<const float> radius, const EdgeStopping& e, int n) {
    if (n < 1 || n > kMaxPenumbraTaps) throw std::invalid_argument("penumbra filter: taps outside 1..128");
    const std::array<glm::vec2, kMaxPenumbraTaps> taps = spiral(n);
    std::vector<float> out(v.begin(), v.end());
    tbb::parallel_for(0, g.height, [&](int j) {
        for (int i = 0; i < g.width; ++i) {
            const size_t k = g.index(i, j);
            if (g.hit[k] && radius[k] >= 0.5f) out[k] = filterAtRadius(v, g, f, radius[k], e, taps, n, i, j);
        }
    });
    return out;
}

}  // namespace shadowlab
