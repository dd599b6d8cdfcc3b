#include "shadows/virtual/local_lookup.h"

#include <algorithm>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include "shading/lights.h"

namespace shadowlab::vsm {

LookupResult lookUpLocalPages(const GBuffer& g, const Light& light, const MipChain& chain, const BiasSettings& bias,
                              const std::vector<PixelLevel>& levels, const PageTable& table, const PagePool& pool) {
    // Each level as the one map a receiver is mapped into (only its matrices are read).
    std::vector<DepthMap> levelMaps(size_t(chain.levelCount()));
    for (int l = 0; l < chain.levelCount(); ++l) {
        DepthMap& map = levelMaps[size_t(l)];
        map.size = chain.mipTexels(chain.mipOfLevel(l));
        map.texelFromWorld = chain.texelFromWorld(l);
        map.worldFromTexel = glm::inverse(map.texelFromWorld);
    }
    const LightReach reaches(light);
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
                    const DepthMap& map = levelMaps[size_t(p.level)];
                    const MapReceiver r = mapReceiverFromPoint(map, glm::dvec3(g.position[k]), glm::dvec3(g.normal[k]),
                                                               chain.apex, bias);
                    // Clamped to the mip, as DepthMap::at clamps to a map's border.
                    const int tx = std::clamp(texelIndexOf(r.texel.x), 0, map.size - 1);
                    const int ty = std::clamp(texelIndexOf(r.texel.y), 0, map.size - 1);
                    const PageKey key{p.level, tx / chain.pageTexels, ty / chain.pageTexels};
                    const int32_t physical = table.physical(key);
                    if (physical == kNoPhysicalPage || !table.valid(key)) {
                        ++c.missing, out.visibility[k] = 1.0f;
                        continue;
                    }
                    const float stored = pool.at(physical, tx - key.x * chain.pageTexels, ty - key.y * chain.pageTexels);
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
