// Backprojection, stage 1: the occluders a receiver's view of the light can meet, as the
// shadow map sees them (Guennebaud, Barthe and Paulin 2006, "Real-time Soft Shadow Mapping
// by Backprojection", section 3: every shadow-map texel is a micro-patch, a square facing
// the light at its depth; RTR 4th ed., 7.6). The search region is the light's cone from the
// receiver cut at the map's near plane (soft_shadow_map.h), the region PCSS searches. Where
// it spans more than maxNodes texels on a side, the min/max hierarchy's nodes stand in for
// texels (their section 4.1, "adaptive precision"): the first level whose nodes cover it in
// at most maxNodes per side, each node a patch at the least depth it holds, so a mixed node
// counts as occluder (a node's worth of dilation, gone as the map's resolution grows).
#pragma once

#include <vector>

#include "shadows/depth_map.h"
#include "shadows/maps/min_max_hierarchy.h"
#include "shadows/maps/shadow_bias.h"

namespace shadowlab {

struct PatchGrid {
    int level = 0;                 // 0: texels, else a level of the hierarchy
    int x0 = 0, y0 = 0;            // the first node, in nodes of that level
    int width = 0, height = 0;     // nodes per side
    std::vector<float> depth;      // window depth of each node's patch; 1: not an occluder
    int occluders = 0;

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
