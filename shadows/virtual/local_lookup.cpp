#include "shadows/virtual/local_lookup.h"

#include <algorithm>


namespace shadowlab::vsm {

LookupResult lookUpLocalPages(const GBuffer& g, const Light& light, const MipChain& chain, const BiasSettings& bias,
                              const PcfKernel& filter, const std::vector<PixelLevel>& levels, const PageTable& table,
                              const PagePool& pool) {
    const std::vector<DepthMap> maps = levelMaps(chain);
    const PageTexels texels(chain.pageTexels, table, pool);
    return lookUpEachPixel(g, light, levels, [&](size_t k, const PixelLevel& p, bool& missing) {
        const DepthMap& map = maps[size_t(p.level)];
        const MapReceiver r =
            mapReceiverFromPoint(map, glm::dvec3(g.position[k]), glm::dvec3(g.normal[k]), chain.apex, bias);
        PageTexels::Cursor cursor;
        const auto litAt = [&](int x, int y) {
            // Clamped to the mip, as DepthMap::at clamps to a map's border.
            x = std::clamp(x, 0, map.size - 1), y = std::clamp(y, 0, map.size - 1);
            const float stored = texels.at(p.level, x, y, cursor);
            missing |= stored == PageTexels::kMissingTexel;
            return stored == PageTexels::kMissingTexel || r.litByStored(stored, x, y);
        };
        const glm::dvec2 rotation = kernelRotation(filter, k, g.width);
        return float(pcfLitFraction(filter, r.texel, rotation, litAt));
    });
}

}  // namespace shadowlab::vsm
