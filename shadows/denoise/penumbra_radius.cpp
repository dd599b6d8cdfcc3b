#include "shadows/denoise/penumbra_radius.h"

#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>

namespace shadowlab {
namespace {

// The mean distance of the blocked rays within the window; +inf where there are none.
float nearbyOccluderDistance(const DenoiseInputs& in, int i, int j, int radius) {
    const GBuffer& g = in.gbuffer;
    float sum = 0.0f;
    int count = 0;
    for (int y = std::max(j - radius, 0); y <= std::min(j + radius, g.height - 1); ++y) {
        for (int x = std::max(i - radius, 0); x <= std::min(i + radius, g.width - 1); ++x) {
            const size_t q = g.index(x, y);
            const float d = in.occluderDistance[q];
            if (g.hit[q] && d > 0.0f && std::isfinite(d)) sum += d, ++count;
        }
    }
    return count ? sum / float(count) : INFINITY;
}

// tan of the light's angular radius seen from an occluder `d` in front of P.
float lightTangent(const DenoiseLight& light, const glm::vec3& P, float d) {
    if (light.directional) return light.tanAngularRadius;
    const float toOccluder = glm::length(light.position - P) - d;
    return toOccluder > 0.0f ? light.radius / toOccluder : 0.0f;   // an occluder behind the light casts none
}

}  // namespace

std::vector<float> penumbraRadius(const DenoiseInputs& in, const SurfaceFeatures& f, const PenumbraRadiusSettings& s) {
    const GBuffer& g = in.gbuffer;
    std::vector<float> radius(g.pixelCount(), 0.0f);
    tbb::parallel_for(0, g.height, [&](int j) {
        for (int i = 0; i < g.width; ++i) {
            const size_t k = g.index(i, j);
            if (!g.hit[k]) continue;
            const float d = nearbyOccluderDistance(in, i, j, s.searchRadius);
            if (!std::isfinite(d)) continue;
            const float width = d * lightTangent(in.light, g.position[k], d);
            radius[k] = std::min(width * in.view.focalPixels / f.depth[k], s.maxRadius);
        }
    });
    return radius;
}

}  // namespace shadowlab
