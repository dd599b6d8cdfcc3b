// Backprojection, gap closing: which neighbouring texels of the map, and which neighbouring
// nodes of each of the min/max hierarchy's levels, lie on one surface, so that their
// patches share their corners (back_projection.h) and no light shows between them
// (Guennebaud et al. 2006, section 3.3; the rule is this project's). Computed once per
// frame: it depends on the map alone, not on the receiver.
//
// The rule compares the step between two neighbours' window depths (a node: its least
// depth) with the steps beside it: before and after it on the same row or column, and
// across that line at both ends, the smaller of the two one-sided steps (the other side
// may be another surface). Window depth is affine in texel coordinates over a plane, so
// a plane's steps are equal; along a convex or concave profile they grow or shrink in
// turn, so no step exceeds the larger of its neighbours on the line, however steep the
// surface is as the light sees it (a sphere near its silhouette, which the former fixed
// threshold on relative depth split). An edge between two surfaces is a step that stands
// out from the steps on both sides (a plate over a rail far below: over 100 times). Joined
// unless the step is more than edgeRatio times the largest step beside it; surface_joins.cpp
// says what the default allows for and what the depths cannot tell apart.
#pragma once

#include <cstdint>
#include <vector>

#include "shadows/depth_map.h"
#include "shadows/maps/min_max_hierarchy.h"

namespace shadowlab {

class SurfaceJoins {
public:
    SurfaceJoins(const DepthMap& map, const MinMaxHierarchy& hierarchy, double edgeRatio);

    // Whether node (x, y) of `level` (0: texels) is on one surface with (x + 1, y), and with
    // (x, y + 1); false past the last node.
    bool right(int level, int x, int y) const { return bit(level, x, y, 1u); }
    bool down(int level, int x, int y) const { return bit(level, x, y, 2u); }

private:
    bool bit(int level, int x, int y, uint8_t which) const;

    // Per level (0, then the hierarchy's from kFirstLevel): nodes per side, and per node bit
    // 0 joined to the node on its right, bit 1 to the one below.
    std::vector<int> sizes_;
    std::vector<std::vector<uint8_t>> joins_;
};

}  // namespace shadowlab
