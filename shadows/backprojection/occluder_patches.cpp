#include "shadows/backprojection/occluder_patches.h"

#include <algorithm>
#include <cmath>

namespace shadowlab {

int patchLevelFor(int span, int maxNodes, int levels) {
    if (span < maxNodes) return 0;
    int level = MinMaxHierarchy::kFirstLevel;
    while (level < levels && (span >> level) + 2 > maxNodes) ++level;   // at most maxNodes per side
    return level;
}

void gatherPatches(const DepthMap& map, const MinMaxHierarchy& hierarchy, const MapReceiver& r, int x0, int y0,
                   int x1, int y1, int maxNodes, PatchGrid& out) {
    out.level = patchLevelFor(std::max(x1 - x0, y1 - y0), maxNodes, hierarchy.levels());
    out.x0 = x0 >> out.level, out.y0 = y0 >> out.level;
    out.width = (x1 >> out.level) - out.x0 + 1, out.height = (y1 >> out.level) - out.y0 + 1;
    out.depth.assign(size_t(out.width) * size_t(out.height), 1.0f);
    out.occluders = 0;
    const double nodeWidth = double(1 << out.level), halfWidth = 0.5 * (nodeWidth - 1.0);
    const double planeSpread = (std::abs(r.depthSlope.x) + std::abs(r.depthSlope.y)) * halfWidth;
    for (int j = 0; j < out.height; ++j) {
        for (int i = 0; i < out.width; ++i) {
            const int x = out.x0 + i, y = out.y0 + j;
            float depth = 1.0f;
            if (out.level == 0) {
                if (!r.litBy(map, x, y)) depth = map.at(x, y);
            } else {
                const float least = hierarchy.node(out.level, x, y).least;
                const double planeLeast = r.depthAt({(x + 0.5) * nodeWidth, (y + 0.5) * nodeWidth}) - planeSpread;
                if (least < 1.0f && double(least) + r.tolerance < planeLeast) depth = least;
            }
            out.depth[size_t(j) * size_t(out.width) + size_t(i)] = depth;
            out.occluders += depth < 1.0f;
        }
    }
}

}  // namespace shadowlab
