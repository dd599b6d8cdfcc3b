#include "shadows/virtual/local_invalidation.h"

#include <algorithm>

namespace shadowlab::vsm {

PageRange localPagesUnder(const Aabb& box, const MipChain& chain, int level) {
    const int32_t last = chain.pagesPerSide(chain.mipOfLevel(level)) - 1;
    bool behind = false;
    const std::optional<TexelRect> rect = texelRectOf(box, chain.texelFromWorld(level), behind);
    if (behind) return {0, 0, -1, -1};
    if (!rect) return {0, 0, last, last};
    const auto page = [&](double c) { return std::clamp(pageOf(c, chain.pageTexels), int32_t(0), last); };
    const PageRange r{page(rect->lo.x), page(rect->lo.y), page(rect->hi.x), page(rect->hi.y)};
    // A rectangle wholly beside the mip clamps to its border pages: it covers none of them.
    const double side = chain.mipTexels(chain.mipOfLevel(level));
    if (rect->hi.x < 0.0 || rect->hi.y < 0.0 || rect->lo.x >= side || rect->lo.y >= side) return {0, 0, -1, -1};
    return r;
}

int invalidateLocalUnder(const std::vector<Aabb>& boxes, const MipChain& chain, PageTable& table) {
    int invalidated = 0;
    for (const Aabb& box : boxes) {
        for (int level = 0; level < chain.levelCount(); ++level) {
            const PageRange r = localPagesUnder(box, chain, level);
            if (r.x0 <= r.x1 && r.y0 <= r.y1) invalidated += table.invalidateBox(level, r.x0, r.y0, r.x1, r.y1);
        }
    }
    return invalidated;
}

}  // namespace shadowlab::vsm
