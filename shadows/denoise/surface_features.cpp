#include "shadows/denoise/surface_features.h"

#include <tbb/parallel_for.h>

namespace shadowlab {
namespace {

// The depth's change per pixel along one axis at k: the central difference where both
// neighbours are hit, one-sided where only one is, 0 where neither is.
float axisGradient(const GBuffer& g, const std::vector<float>& z, size_t k, bool hasBefore, size_t before,
                   bool hasAfter, size_t after) {
    const bool b = hasBefore && g.hit[before], a = hasAfter && g.hit[after];
    if (a && b) return 0.5f * (z[after] - z[before]);
    if (a) return z[after] - z[k];
    if (b) return z[k] - z[before];
    return 0.0f;
}

}  // namespace

SurfaceFeatures surfaceFeatures(const GBuffer& g, const DenoiseView& view) {
    SurfaceFeatures f;
    const size_t n = g.pixelCount();
    f.depth.assign(n, 0.0f);
    f.depthGradient.assign(n, glm::vec2(0.0f));
    for (size_t k = 0; k < n; ++k)
        if (g.hit[k]) f.depth[k] = glm::length(g.position[k] - view.eye);
    tbb::parallel_for(0, g.height, [&](int j) {
        for (int i = 0; i < g.width; ++i) {
            const size_t k = g.index(i, j);
            if (!g.hit[k]) continue;
            f.depthGradient[k] = {axisGradient(g, f.depth, k, i > 0, k - 1, i + 1 < g.width, k + 1),
                                  axisGradient(g, f.depth, k, j > 0, k - g.width, j + 1 < g.height, k + g.width)};
        }
    });
    return f;
}

}  // namespace shadowlab
