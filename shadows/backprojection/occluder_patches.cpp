#include "shadows/backprojection/occluder_patches.h"

#include <algorithm>
#include <cmath>

namespace shadowlab {
namespace {

// Float steps (ulps of the larger window depth) that rounding can add to a step between
// neighbours beyond the steps beside it: each stored depth is within half a step of its
// surface's, so a plane's steps differ by up to two, and the polygon offset's constant
// part (4 steps: BiasSettings' default, which renderPcssMap draws with) by a few more
// where the depths cross a power of two.
constexpr double kDepthRoundingSteps = 8.0;

// Whether a node of `level` at (x, y) may occlude (its plane and residuals do not prove it
// lit, so a floor's node, on the receiver's plane, is left out) and whether all of it does
// (no empty texel, and its greatest depth nearer than the plane anywhere over it).
struct NodeClass {
    bool some = false, all = false;
    float least = 1.0f;
};
NodeClass classify(const MinMaxHierarchy& hierarchy, const MapReceiver& r, int level, int x, int y) {
    const float least = hierarchy.node(level, x, y).least;
    return {least < 1.0f && !hierarchy.nodeProvedLit(r, level, x, y), hierarchy.nodeShadowed(r, level, x, y), least};
}

// The coarsest level whose nodes at window depth `depth` back-project no wider than one of
// the light's samples (0: texels; the hierarchy has no level 1).
int sampleLevel(const SoftShadowMap& soft, const PatchReceiver& p, float depth) {
    const double d = std::min(soft.distanceOf(depth), p.dr);
    const glm::dvec2 w = sampleWidthTexels(soft, p.dr, d);
    const double texels = std::min(w.x, w.y) / p.samplesPerAxis;
    int level = 0;
    while (level < 30 && double(2 << level) <= texels) ++level;
    return level < MinMaxHierarchy::kFirstLevel ? 0 : level;
}

// A mixed node: one patch at its least depth once it is no wider than a light sample, else
// its children (the next level down, or texels below the hierarchy's first level), the
// solid ones as patches and the mixed ones refined again.
void refine(const SoftShadowMap& soft, const MinMaxHierarchy& hierarchy, const PatchReceiver& p, int level, int x,
            int y, float least, PatchGrid& out) {
    if (level <= sampleLevel(soft, p, least)) return void(out.fine.push_back({level, x, y, least}));
    const int down = level - 1 >= MinMaxHierarchy::kFirstLevel ? level - 1 : 0;
    const int per = 1 << (level - down), size = down == 0 ? soft.map.size : hierarchy.sizeOf(down);
    for (int j = y * per; j < std::min((y + 1) * per, size); ++j) {
        for (int i = x * per; i < std::min((x + 1) * per, size); ++i) {
            if (down == 0) {
                if (!p.r.litBy(soft.map, i, j)) out.fine.push_back({0, i, j, soft.map.at(i, j)});
                continue;
            }
            const NodeClass c = classify(hierarchy, p.r, down, i, j);
            if (c.all) out.fine.push_back({down, i, j, c.least});
            else if (c.some) refine(soft, hierarchy, p, down, i, j, c.least, out);
        }
    }
}

// The map's depth at node (x, y) of `level`, whatever it holds (an occluder or not, or
// nothing: 1): a texel, or a node's least depth; clamped to the map.
float surfaceDepth(const SoftShadowMap& soft, const MinMaxHierarchy& hierarchy, int level, int x, int y) {
    if (level == 0) return soft.map.at(x, y);
    const int last = hierarchy.sizeOf(level) - 1;
    return hierarchy.node(level, std::clamp(x, 0, last), std::clamp(y, 0, last)).least;
}

// Whether node (i, j) and its neighbour (i + dx, j + dy) lie on one surface
// (occluder_patches.h): the step between them is at most edgeRatio times the largest step
// beside it, give or take rounding. Beside it: the steps before and after it on its line,
// and across the line at each end the smaller one-sided step (the other side may be
// another surface). Across matters where the line runs along a steep slope: the slope-
// scaled polygon offset (1.5 texels of a triangle's steepest slope) then changes from
// facet to facet by more than the steps along the line.
bool oneSurface(const PatchGrid& grid, int i, int j, int dx, int dy, double edgeRatio) {
    const double a = grid.surfaceAt(i, j), b = grid.surfaceAt(i + dx, j + dy);
    const double step = std::abs(b - a), rounding = kDepthRoundingSteps * std::ldexp(std::max(a, b), -23);
    const double along = std::max(std::abs(a - grid.surfaceAt(i - dx, j - dy)),
                                  std::abs(grid.surfaceAt(i + 2 * dx, j + 2 * dy) - b));
    if (step <= edgeRatio * along + rounding) return true;
    const auto across = [&](int x, int y, double here) {
        return std::min(std::abs(here - grid.surfaceAt(x - dy, y - dx)),
                        std::abs(grid.surfaceAt(x + dy, y + dx) - here));
    };
    return step <= edgeRatio * std::max(across(i, j, a), across(i + dx, j + dy, b)) + rounding;
}

// Sets the grid's joins. On a convex or concave surface a step is at most 1 times the
// larger step beside it; edgeRatio (8 by default) also allows for the polygon offset
// (+1.5) and for faces a texel or two wide (a box's side seen grazing), whose steps
// beside belong to the next face (about 4 on two-heights' rail), twice over; two-heights'
// plate and a rail partly under it stay apart up to 100. The map cannot tell a steep
// silhouette in front of a surface that goes on behind it (joined: right) from one in
// front of a surface that ends there (joined too: a skirt, too dark); a flat edge in front
// of a farther surface stays apart either way (one depth layer: the hidden part is lost).
void joinSurfaces(const SoftShadowMap& soft, const MinMaxHierarchy& hierarchy, double edgeRatio, PatchGrid& grid) {
    grid.surface.resize(size_t(grid.width + 3) * size_t(grid.height + 3));
    for (int j = -1; j <= grid.height + 1; ++j) {
        for (int i = -1; i <= grid.width + 1; ++i) {
            grid.surfaceAt(i, j) = surfaceDepth(soft, hierarchy, grid.level, grid.x0 + i, grid.y0 + j);
        }
    }
    for (int j = 0; j < grid.height; ++j) {
        for (int i = 0; i < grid.width; ++i) {
            if (grid.at(i, j) >= 1.0f) continue;
            uint8_t& joins = grid.joins[size_t(j) * size_t(grid.width) + size_t(i)];
            const bool right = i + 1 < grid.width && grid.at(i + 1, j) < 1.0f;
            const bool down = j + 1 < grid.height && grid.at(i, j + 1) < 1.0f;
            if (right && oneSurface(grid, i, j, 1, 0, edgeRatio)) joins |= 1u;
            if (down && oneSurface(grid, i, j, 0, 1, edgeRatio)) joins |= 2u;
        }
    }
}

}  // namespace

void gatherPatches(const SoftShadowMap& soft, const MinMaxHierarchy& hierarchy, const PatchReceiver& p, int x0,
                   int y0, int x1, int y1, const PatchSettings& settings, PatchGrid& out) {
    out.level = readingLevelFor(std::max(x1 - x0, y1 - y0), settings.maxNodes, hierarchy.levels());
    out.x0 = x0 >> out.level, out.y0 = y0 >> out.level;
    out.width = (x1 >> out.level) - out.x0 + 1, out.height = (y1 >> out.level) - out.y0 + 1;
    out.depth.assign(size_t(out.width) * size_t(out.height), 1.0f);
    out.fine.clear();
    int gridPatches = 0;
    for (int j = 0; j < out.height; ++j) {
        for (int i = 0; i < out.width; ++i) {
            const int x = out.x0 + i, y = out.y0 + j;
            float depth = 1.0f;
            if (out.level == 0) {
                if (!p.r.litBy(soft.map, x, y)) depth = soft.map.at(x, y);
            } else {
                const NodeClass c = classify(hierarchy, p.r, out.level, x, y);
                if (c.all) depth = c.least;
                else if (c.some) refine(soft, hierarchy, p, out.level, x, y, c.least, out);
            }
            out.depth[size_t(j) * size_t(out.width) + size_t(i)] = depth;
            gridPatches += depth < 1.0f;
        }
    }
    out.occluders = gridPatches + int(out.fine.size());
    out.joins.assign(out.depth.size(), 0);
    if (gridPatches > 0) joinSurfaces(soft, hierarchy, settings.edgeRatio, out);
}

}  // namespace shadowlab
