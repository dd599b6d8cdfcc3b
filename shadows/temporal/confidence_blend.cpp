#include "shadows/temporal/confidence_blend.h"

#include <tbb/parallel_for.h>

#include "raster/portable_math.h"

namespace shadowlab {

void blendByConfidence(std::span<const float> tests, std::span<const float> confidence, double exponent,
                       const GBuffer& g, const Reprojection* reprojection, std::span<const float> before,
                       std::vector<float>& after) {
    if (reprojection) requireHistoryOf(*reprojection, before.size(), "confidence blend");
    after.assign(g.pixelCount(), 0.0f);
    tbb::parallel_for(0, g.height, [&](int j) {
        for (int i = 0; i < g.width; ++i) {
            const size_t k = g.index(i, j);
            if (!g.hit[k]) continue;
            if (!reprojection || !reprojection->kept[k]) {
                after[k] = tests[k];
                continue;
            }
            const float history = reprojection->resample(before, k);
            // c^m by the portable pow: the same bits on every CPU.
            const double c = confidence[k];
            const double weight = exponent == 0.0 ? 1.0 : c > 0.0 ? portable::pow(c, exponent) : 0.0;
            after[k] = float(history + weight * (double(tests[k]) - history));
        }
    });
}

}  // namespace shadowlab
