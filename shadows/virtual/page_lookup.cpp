#include "shadows/virtual/page_lookup.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include "shading/lights.h"

namespace shadowlab::vsm {

double biasReachTexels(const BiasSettings& bias) {
    return bias.mode == BiasMode::NormalOffset ? bias.normalOffsetTexels : 0.0;
}

LookupResult lookUpPages(const GBuffer& g, const Light& sun, const LightFrame& frame, const ClipmapSettings& clipmap,
                         const DepthRange& range, const BiasSettings& bias, const std::vector<PixelLevel>& levels,
                         const PageTable& table, const PagePool& pool) {
    // Each level as the one map a receiver is mapped into (only its matrices are read).
    std::vector<DepthMap> levelMaps(size_t(clipmap.levelCount()));
    for (int l = 0; l < clipmap.levelCount(); ++l) {
        levelMaps[size_t(l)].texelFromWorld = levelTexelFromWorld(frame, clipmap, range, clipmap.firstLevel + l);
        levelMaps[size_t(l)].worldFromTexel = glm::inverse(levelMaps[size_t(l)].texelFromWorld);
    }
    const glm::dvec3 towardsLight = glm::normalize(glm::dvec3(sun.direction));
    const LightReach reaches(sun);
    LookupResult out{std::vector<float>(g.pixelCount(), 0.0f)};
    struct Counts {
        size_t missing = 0, unleveled = 0;
    };
    const Counts counts = tbb::parallel_reduce(
        tbb::blocked_range<int>(0, g.height), Counts{},
        [&](const tbb::blocked_range<int>& rows, Counts c) {
            for (int j = rows.begin(); j < rows.end(); ++j) {
                for (int i = 0; i < g.width; ++i) {
                    const size_t k = g.index(i, j);
                    if (!g.hit[k] || !reaches(g.position[k], g.normal[k])) continue;   // V = 0
                    const PixelLevel& p = levels[k];
                    if (p.level == kNoLevel) {
                        ++c.unleveled, out.visibility[k] = 1.0f;
                        continue;
                    }
                    const MapReceiver r = mapReceiver(levelMaps[size_t(p.level)], glm::dvec3(g.position[k]),
                                                      glm::dvec3(g.normal[k]), towardsLight, bias);
                    const int tx = texelIndexOf(r.texel.x), ty = texelIndexOf(r.texel.y);
                    const PageKey key{clipmap.firstLevel + p.level, pageOf(tx, clipmap.pageTexels),
                                      pageOf(ty, clipmap.pageTexels)};
                    const int32_t physical = table.physical(key);
                    if (physical == kNoPhysicalPage || !table.valid(key)) {
                        ++c.missing, out.visibility[k] = 1.0f;
                        continue;
                    }
                    const float stored = pool.at(physical, tx - key.x * clipmap.pageTexels, ty - key.y * clipmap.pageTexels);
                    out.visibility[k] = r.litByStored(stored, tx, ty) ? 1.0f : 0.0f;
                }
            }
            return c;
        },
        [](Counts a, const Counts& b) {
            a.missing += b.missing, a.unleveled += b.unleveled;
            return a;
        });
    out.missingPixels = counts.missing, out.unleveledPixels = counts.unleveled;
    return out;
}

}  // namespace shadowlab::vsm
