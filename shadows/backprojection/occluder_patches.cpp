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

namespace {

// The refinement of a mixed node (level, x, y) into fine patches: its texels, or the nodes
// two levels down (never below the hierarchy's first level), each where it may occlude.
void refine(const DepthMap& map, const MinMaxHierarchy& hierarchy, const MapReceiver& r, int level, int x, int y,
            PatchGrid& out) {
    const int down = (1 << (2 * level)) <= kRefinedTexels ? 0 : std::max(level - 2, MinMaxHierarchy::kFirstLevel);
    const int per = 1 << (level - down);
    const double width = double(1 << down), halfWidth = 0.5 * (width - 1.0);
    const double planeSpread = (std::abs(r.depthSlope.x) + std::abs(r.depthSlope.y)) * halfWidth;
    for (int j = y * per; j < (y + 1) * per; ++j) {
        for (int i = x * per; i < (x + 1) * per; ++i) {
            if (down == 0) {
                if (i < map.size && j < map.size && !r.litBy(map, i, j)) out.fine.push_back({0, i, j, map.at(i, j)});
                continue;
            }
            if (i >= hierarchy.sizeOf(down) || j >= hierarchy.sizeOf(down)) continue;
            const float least = hierarchy.node(down, i, j).least;
            const double planeLeast = r.depthAt({(i + 0.5) * width, (j + 0.5) * width}) - planeSpread;
            if (least < 1.0f && double(least) + r.tolerance < planeLeast) out.fine.push_back({down, i, j, least});
        }
    }
}

}  // namespace

void gatherPatches(const DepthMap& map, const MinMaxHierarchy& hierarchy, const MapReceiver& r, int x0, int y0,
                   int x1, int y1, int maxNodes, PatchGrid& out) {
    out.level = patchLevelFor(std::max(x1 - x0, y1 - y0), maxNodes, hierarchy.levels());
    out.x0 = x0 >> out.level, out.y0 = y0 >> out.level;
    out.width = (x1 >> out.level) - out.x0 + 1, out.height = (y1 >> out.level) - out.y0 + 1;
    out.depth.assign(size_t(out.width) * size_t(out.height), 1.0f);
    out.fine.clear();
    const double nodeWidth = double(1 << out.level), halfWidth = 0.5 * (nodeWidth - 1.0);
    const double planeSpread = (std::abs(r.depthSlope.x) + std::abs(r.depthSlope.y)) * halfWidth;
    int gridPatches = 0;
    for (int j = 0; j < out.height; ++j) {
        for (int i = 0; i < out.width; ++i) {
            const int x = out.x0 + i, y = out.y0 + j;
            float depth = 1.0f;
            if (out.level == 0) {
                if (!r.litBy(map, x, y)) depth = map.at(x, y);
            } else {
                // Where the receiver's plane is least deep over the node: a texel nearer than
                // that occludes wherever it lies in the node.
                const DepthRange range = hierarchy.node(out.level, x, y);
                const double planeLeast = r.depthAt({(x + 0.5) * nodeWidth, (y + 0.5) * nodeWidth}) - planeSpread;
                const bool some = range.least < 1.0f && double(range.least) + r.tolerance < planeLeast;
                const bool all = double(range.greatest) + r.tolerance < planeLeast;
                if (all) depth = range.least;
                else if (some) refine(map, hierarchy, r, out.level, x, y, out);
            }
            out.depth[size_t(j) * size_t(out.width) + size_t(i)] = depth;
            gridPatches += depth < 1.0f;
        }
    }
    out.occluders = gridPatches + int(out.fine.size());
}

}  // namespace shadowlab
