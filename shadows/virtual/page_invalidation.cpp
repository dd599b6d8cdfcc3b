#include "shadows/virtual/page_invalidation.h"

#include <cmath>

namespace shadowlab::vsm {

PageRange pagesUnder(const Aabb& box, const LightFrame& frame, const ClipmapSettings& clipmap, int level) {
    glm::dvec2 lo(INFINITY), hi(-INFINITY);
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec3 P{corner & 1 ? box.max.x : box.min.x, corner & 2 ? box.max.y : box.min.y,
                           corner & 4 ? box.max.z : box.min.z};
        const glm::dvec2 t = texelOf(clipmap, level, frame.local(P));
        lo = glm::min(lo, t), hi = glm::max(hi, t);
    }
    const auto page = [&](double c) { return pageOf(c, clipmap.pageTexels); };
    return {page(lo.x), page(lo.y), page(hi.x), page(hi.y)};
}

std::vector<Aabb> movedBoxes(const std::vector<Aabb>& last, const std::vector<Aabb>& now) {
    std::vector<Aabb> moved;
    for (size_t i = 0; i < now.size(); ++i) {
        if (last[i].min != now[i].min || last[i].max != now[i].max) moved.push_back(last[i]), moved.push_back(now[i]);
    }
    return moved;
}

int invalidateUnder(const std::vector<Aabb>& boxes, const LightFrame& frame, const ClipmapSettings& clipmap,
                    PageTable& table) {
    int invalidated = 0;
    for (const Aabb& box : boxes) {
        for (int level = clipmap.firstLevel; level <= clipmap.lastLevel; ++level) {
            const PageRange r = pagesUnder(box, frame, clipmap, level);
            invalidated += table.invalidateBox(level, r.x0, r.y0, r.x1, r.y1);
        }
    }
    return invalidated;
}

}  // namespace shadowlab::vsm
