#include "shadows/backprojection/occluder_patches.h"

#include <algorithm>
#include <cmath>

namespace shadowlab {
namespace {

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

// Whether a node's patches, at depth `least` or (refined) anywhere from there to the
// receiver, all project off the light.
bool offLight(const PatchReceiver& p, int level, int x, int y, float least, float deepest) {
    const double width = double(1 << level);
    return p.pyramid.misses(x * width, y * width, (x + 1) * width, (y + 1) * width, least, deepest);
}

// A mixed node: one patch at its least depth once it is no wider than a light sample, else
// its children (the next level down, or texels below the hierarchy's first level), the
// solid ones as patches and the mixed ones refined again; nothing where it all projects
// off the light.
void refine(const SoftShadowMap& soft, const MinMaxHierarchy& hierarchy, const PatchReceiver& p, int level, int x,
            int y, float least, PatchGrid& out) {
    if (level <= sampleLevel(soft, p, least)) {
        if (!offLight(p, level, x, y, least, least)) out.fine.push_back({level, x, y, least});
        return;
    }
    if (offLight(p, level, x, y, least, 1.0f)) return;
    const int down = level - 1 >= MinMaxHierarchy::kFirstLevel ? level - 1 : 0;
    const int per = 1 << (level - down), size = down == 0 ? soft.map.size : hierarchy.sizeOf(down);
    for (int j = y * per; j < std::min((y + 1) * per, size); ++j) {
        for (int i = x * per; i < std::min((x + 1) * per, size); ++i) {
            if (down == 0) {
                const float depth = soft.map.at(i, j);
                if (!p.r.litBy(soft.map, i, j) && !offLight(p, 0, i, j, depth, depth))
                    out.fine.push_back({0, i, j, depth});
                continue;
            }
            const NodeClass c = classify(hierarchy, p.r, down, i, j);
            if (c.all) {
                if (!offLight(p, down, i, j, c.least, c.least)) out.fine.push_back({down, i, j, c.least});
            } else if (c.some) {
                refine(soft, hierarchy, p, down, i, j, c.least, out);
            }
        }
    }
}

}  // namespace

void gatherPatches(const SoftShadowMap& soft, const MinMaxHierarchy& hierarchy, const PatchReceiver& p, int x0,
                   int y0, int x1, int y1, int maxNodes, PatchGrid& out) {
    out.level = readingLevelFor(std::max(x1 - x0, y1 - y0), maxNodes, hierarchy.levels());
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
}

}  // namespace shadowlab
