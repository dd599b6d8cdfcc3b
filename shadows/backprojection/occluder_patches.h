// Backprojection, stage 1: the occluders a receiver's view of the light can meet, as the
// shadow map sees them (Guennebaud, Barthe and Paulin 2006, "Real-time Soft Shadow Mapping
// by Backprojection", section 3: every shadow-map texel is a micro-patch, a square facing
// the light at its depth; RTR 4th ed., 7.6). The search region is the light's cone from the
// receiver cut at the map's near plane (soft_shadow_map.h), the region PCSS searches. Where
// it spans more than maxNodes texels on a side, the min/max hierarchy's nodes stand in for
// texels (their section 4.1, "adaptive precision"): the first level whose nodes cover it in
// at most maxNodes per side. A node whose every texel occludes is one patch at its least
// depth. A mixed node (an occluder's edge: some texels occlude, some do not) is refined, as
// the hierarchy allows: into its texels up to kRefinedTexels of them, else into the nodes
// two levels down, each a patch at its least depth, so a thin occluder (a rail under a
// wide plate) keeps its width instead of growing to a node's.
#pragma once

#include <vector>

#include "shadows/depth_map.h"
#include "shadows/maps/min_max_hierarchy.h"
#include "shadows/maps/shadow_bias.h"

namespace shadowlab {

// A patch outside the grid: a texel (level 0) or a node of a refined mixed node.
struct FinePatch {
    int level = 0;
    int x = 0, y = 0;              // in nodes of its level
    float depth = 1.0f;            // window depth
};

inline constexpr int kRefinedTexels = 64;   // a mixed node of at most 8 x 8 texels is refined to texels

struct PatchGrid {
    int level = 0;                 // 0: texels, else a level of the hierarchy
    int x0 = 0, y0 = 0;            // the first node, in nodes of that level
    int width = 0, height = 0;     // nodes per side
    std::vector<float> depth;      // window depth of each node's patch; 1: none (no occluder, or refined)
    std::vector<FinePatch> fine;   // the refined mixed nodes' patches
    int occluders = 0;             // patches, the grid's and the fine ones

    float at(int i, int j) const { return depth[size_t(j) * size_t(width) + size_t(i)]; }
};

// The patches of texels [x0, x1] x [y0, y1] (inside the map) for receiver r (its plane,
// receiver-plane bias): a texel occludes where r.litBy says shadowed; a node where its
// least depth plus the compare's tolerance is nearer than the receiver's plane anywhere
// over it (so a floor's own nodes, on the plane, never occlude it).
void gatherPatches(const DepthMap& map, const MinMaxHierarchy& hierarchy, const MapReceiver& r, int x0, int y0,
                   int x1, int y1, int maxNodes, PatchGrid& out);

// The level gatherPatches uses for a region spanning `span` texels: 0 or one of the
// hierarchy's (MinMaxHierarchy::kFirstLevel ...).
int patchLevelFor(int span, int maxNodes, int levels);

}  // namespace shadowlab
