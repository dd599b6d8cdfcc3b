// Backprojection, stage 1: the occluders a receiver's view of the light can meet, as the
// shadow map sees them (Guennebaud, Barthe and Paulin 2006, "Real-time Soft Shadow Mapping
// by Backprojection", section 3: every shadow-map texel is a micro-patch, a square facing
// the light at its depth; RTR 4th ed., 7.6). The search region is the light's cone from the
// receiver cut at the map's near plane (soft_shadow_map.h), the region PCSS searches. Where
// it spans more than maxNodes texels on a side, the min/max hierarchy's nodes stand in for
// texels (their section 4.1, "adaptive precision"): the first level whose nodes cover it in
// at most maxNodes per side. A node whose every texel occludes is one patch at its least
// depth. A mixed node (an occluder's edge: some texels occlude, some do not) is refined
// down the hierarchy until its nodes are no wider, back-projected, than one of the light's
// samples: a node of 2^l texels at distance d from the light covers 2^l / w(d) of the
// light's width, w(d) the light's cone from the receiver in texels at d (eq. 7.6 in
// texels), so the refinement stops at 2^l <= w(d) / n for n samples per axis. A thin
// occluder (a rail under a wide plate) keeps its width to within a sample. A refined node
// whose patches would all project off the light (light_pyramid.h) is left out, with all
// it holds.
#pragma once

#include <vector>

#include "shadows/backprojection/light_pyramid.h"
#include "shadows/depth_map.h"
#include "shadows/filtered/soft_shadow_map.h"
#include "shadows/maps/min_max_hierarchy.h"
#include "shadows/maps/shadow_bias.h"

namespace shadowlab {

// A patch outside the grid: a texel (level 0) or a node of a refined mixed node.
struct FinePatch {
    int level = 0;
    int x = 0, y = 0;              // in nodes of its level
    float depth = 1.0f;            // window depth
};

struct PatchGrid {
    int level = 0;                 // 0: texels, else a level of the hierarchy
    int x0 = 0, y0 = 0;            // the first node, in nodes of that level
    int width = 0, height = 0;     // nodes per side
    std::vector<float> depth;      // window depth of each node's patch; 1: none (no occluder, or refined)
    std::vector<FinePatch> fine;   // the refined mixed nodes' patches
    int occluders = 0;             // patches, the grid's and the fine ones

    float at(int i, int j) const { return depth[size_t(j) * size_t(width) + size_t(i)]; }
};

// What the patches are gathered for: the receiver (its plane, receiver-plane bias; its
// distance dr from the light's centre; its view of the light) and the light's samples per
// axis.
struct PatchReceiver {
    const MapReceiver& r;
    double dr;
    const LightPyramid& pyramid;
    int samplesPerAxis;
};

// The patches of texels [x0, x1] x [y0, y1] (inside the map): a texel occludes where r.litBy
// says shadowed; a node may occlude unless its plane and residuals prove it lit (so a
// floor's own nodes, on the receiver's plane, are left out), and occludes whole where it
// holds no empty texel and its greatest depth is nearer than the receiver's plane anywhere
// over it; the rest, mixed, is refined.
void gatherPatches(const SoftShadowMap& soft, const MinMaxHierarchy& hierarchy, const PatchReceiver& receiver,
                   int x0, int y0, int x1, int y1, int maxNodes, PatchGrid& out);

}  // namespace shadowlab
