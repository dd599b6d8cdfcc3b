#include "shadows/virtual/local_lookup.h"

#include <algorithm>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include "shading/lights.h"

namespace shadowlab::vsm {

LookupResult lookUpLocalPages(const GBuffer& g, const Light& light, const MipChain& chain, const BiasSettings& bias,
                              const PcfKernel& filter, const std::vector<PixelLevel>& levels, const PageTable& table,
                              const PagePool& pool) {
    // Each level as the one map a receiver is mapped into (only its matrices are read).
    std::vector<DepthMap> levelMaps(size_t(chain.levelCount()));
    for (int l = 0; l < chain.levelCount(); ++l) {
        DepthMap& map = levelMaps[size_t(l)];
        map.size = chain.mipTexels(chain.mipOfLevel(l));
        map.texelFromWorld = chain.texelFromWorld(l);
        map.worldFromTexel = glm::inverse(map.texelFromWorld);
    }
    const PageTexels texels(chain.pageTexels, table, pool);
    const bool rotated = filter.settings.kind == FilterKind::Poisson;
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
                    bool missing = false;
                    PageTexels::Cursor cursor;
                    const auto litAt = [&](int x, int y) {
                        // Clamped to the mip, as DepthMap::at clamps to a map's border.
                        x = std::clamp(x, 0, map.size - 1), y = std::clamp(y, 0, map.size - 1);
                        const float stored = texels.at(p.level, x, y, cursor);
                        missing |= stored == PageTexels::kMissingTexel;
                        return stored == PageTexels::kMissingTexel || r.litByStored(stored, x, y);
                    };
                    const glm::dvec2 rotation = rotated ? poissonRotationCosSin(k) : glm::dvec2(1.0, 0.0);
                    out.visibility[k] = float(pcfLitFraction(filter, r.texel, rotation, litAt));
                    c.missing += missing;
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
