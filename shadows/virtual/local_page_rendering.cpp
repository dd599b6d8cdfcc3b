#include "shadows/virtual/local_page_rendering.h"

namespace shadowlab::vsm {

bool boxMeetsPage(const Aabb& box, const glm::dmat4& texelFromWorld, const PageKey& key, int pageTexels) {
    bool behind = false;
    const std::optional<TexelRect> rect = texelRectOf(box, texelFromWorld, behind);
    if (behind) return false;
    if (!rect) return true;
    const double x0 = double(key.x) * pageTexels, y0 = double(key.y) * pageTexels;
    return rect->hi.x >= x0 && rect->lo.x <= x0 + pageTexels && rect->hi.y >= y0 && rect->lo.y <= y0 + pageTexels;
}

void renderLocalPages(const PreparedScene& casters, const std::vector<Aabb>& casterBoxes, const MipChain& chain,
                      std::span<const PageKey> keys, std::span<const int32_t> physical,
                      const raster::PolygonOffset& offset, raster::SimdLevel simd, PageDrawing& drawing, PagePool& pool) {
    if (keys.empty()) return;
    const std::vector<InstanceRange> ranges = instanceRanges(casters.scene());
    const auto setup = [&](size_t k, std::vector<uint32_t>& triangles) {
        const glm::dmat4 texelFromWorld = chain.texelFromWorld(keys[k].level);
        triangles.clear();
        for (size_t i = 0; i < ranges.size(); ++i) {
            if (!boxMeetsPage(casterBoxes[i], texelFromWorld, keys[k], chain.pageTexels)) continue;
            for (uint32_t t = 0; t < ranges[i].triangleCount; ++t) triangles.push_back(ranges[i].firstTriangle + t);
        }
        return chain.pageView(keys[k]);
    };
    drawPages(casters, physical, setup, offset, simd, drawing, pool);
}

}  // namespace shadowlab::vsm
