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
// occluder (a rail under a wide plate) keeps its width to within a sample.
//
// Which neighbouring patches of the grid are one surface, so that back_projection closes
// the gap between them (Guennebaud et al., section 3.3; the rule is this project's): the
// step between their depths against the steps beside it, in window depth, where a plane's
// steps are equal (it is affine in texel coordinates). Along a convex or concave profile
// the steps grow or shrink in turn, so no step exceeds the larger of its neighbours on the
// same line, however steep the surface is seen from the light (a sphere near its
// silhouette, which a fixed threshold on relative depth split); an edge between two
// surfaces stands out from the steps on both sides (a plate over a rail far below: more
// than 100 times). joinSurfaces in the .cpp says what edgeRatio allows for and what the
// map cannot tell apart.
#pragma once

#include <cstdint>
#include <vector>

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
    // Which neighbouring patches are one surface (above): per node, bit 0 joined to the
    // node on its right, bit 1 to the one below.
    std::vector<uint8_t> joins;
    // The map's depth at the nodes and a border around them (one node before, two after),
    // occluding or not: the steps the joins compare.
    std::vector<float> surface;

    float at(int i, int j) const { return depth[index(i, j)]; }
    float& surfaceAt(int i, int j) { return surface[surfaceIndex(i, j)]; }
    float surfaceAt(int i, int j) const { return surface[surfaceIndex(i, j)]; }
    // False outside the grid.
    bool joinedRight(int i, int j) const { return inside(i, j) && (joins[index(i, j)] & 1u); }
    bool joinedDown(int i, int j) const { return inside(i, j) && (joins[index(i, j)] & 2u); }

private:
    size_t index(int i, int j) const { return size_t(j) * size_t(width) + size_t(i); }
    size_t surfaceIndex(int i, int j) const { return size_t(j + 1) * size_t(width + 3) + size_t(i + 1); }
    bool inside(int i, int j) const { return i >= 0 && j >= 0 && i < width && j < height; }
};

// What the patches are gathered for: the receiver (its plane, receiver-plane bias; its
// distance dr from the light's centre) and the light's samples per axis.
struct PatchReceiver {
    const MapReceiver& r;
    double dr;
    int samplesPerAxis;
};

struct PatchSettings {
    int maxNodes;        // nodes per side of a region at most (the level read)
    double edgeRatio;    // a step more than this many times the steps beside it is an edge
};

// The patches of texels [x0, x1] x [y0, y1] (inside the map): a texel occludes where r.litBy
// says shadowed; a node may occlude unless its plane and residuals prove it lit (so a
// floor's own nodes, on the receiver's plane, are left out), and occludes whole where it
// holds no empty texel and its greatest depth is nearer than the receiver's plane anywhere
// over it; the rest, mixed, is refined. Then the grid's neighbouring patches on one
// surface are joined (the fine ones keep their own depths).
void gatherPatches(const SoftShadowMap& soft, const MinMaxHierarchy& hierarchy, const PatchReceiver& receiver,
                   int x0, int y0, int x1, int y1, const PatchSettings& settings, PatchGrid& out);

}  // namespace shadowlab
