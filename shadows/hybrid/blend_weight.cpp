#include <algorithm>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "shadows/hybrid/izb_pcss.h"

namespace shadowlab {

std::vector<float> blendWeights(const GBuffer& g, const SoftShadowMap& soft, const std::vector<float>& blockerDistance,
                                const BlendDistances& distances) {
    std::vector<float> weight(g.pixelCount(), 0.0f);
    const float ramp = 1.0f / (distances.softAboveM - distances.hardBelowM);
    tbb::parallel_for(tbb::blocked_range<int>(0, g.height), [&](const tbb::blocked_range<int>& rows) {
        for (int j = rows.begin(); j < rows.end(); ++j) {
            for (int i = 0; i < g.width; ++i) {
                const size_t k = g.index(i, j);
                if (!g.hit[k] || blockerDistance[k] <= 0.0f) continue;
                const float receiver = float(softReceiver(soft, glm::dvec3(g.position[k])).distance);
                const float occluder = receiver - blockerDistance[k];
                weight[k] = std::clamp((occluder - distances.hardBelowM) * ramp, 0.0f, 1.0f);
            }
        }
    });
    return weight;
}

}  // namespace shadowlab
