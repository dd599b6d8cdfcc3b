#include "shadows/temporal/shadow_test_confidence.h"

#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>

namespace shadowlab {

std::vector<float> shadowTestConfidence(const GBuffer& g, const DepthMap& map, const Light& light,
                                        const BiasSettings& bias) {
    std::vector<float> confidence(g.pixelCount(), 0.0f);
    const bool directional = light.type == LightType::Directional;
    const glm::dvec3 towardsSun = directional ? glm::normalize(glm::dvec3(light.direction)) : glm::dvec3(0.0);
    tbb::parallel_for(0, g.height, [&](int j) {
        for (int i = 0; i < g.width; ++i) {
            const size_t k = g.index(i, j);
            if (!g.hit[k]) continue;
            const glm::dvec3 P(g.position[k]), N(g.normal[k]);
            const MapReceiver r = directional ? mapReceiver(map, P, N, towardsSun, bias)
                                              : mapReceiverFromPoint(map, P, N, glm::dvec3(light.position), bias);
            const glm::dvec2 fromCentre = glm::abs(r.texel - glm::floor(r.texel) - 0.5);
            confidence[k] = float(std::clamp(1.0 - 2.0 * std::max(fromCentre.x, fromCentre.y), 0.0, 1.0));
        }
    });
    return confidence;
}

}  // namespace shadowlab
