// The receiver hierarchy of Gibson et al. 2003 (section 6): the receiver patches clustered
// top-down in an octree, a node split at the middle of its patches' centres into their
// octants until it holds at most `leafSize` patches (8 in the paper), "a broad but relatively
// shallow" hierarchy whose shafts cull large regions of line space at once.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "scenes/bounds.h"

namespace shadowlab {

struct ReceiverNode {
    Aabb bounds;
    uint32_t firstPatch = 0, patchCount = 0;   // range in ReceiverOctree::patches
    int32_t firstChild = -1;                   // -1 at a leaf; else childCount nodes from here
    uint32_t childCount = 0;
    bool leaf() const { return firstChild < 0; }
};

struct ReceiverOctree {
    std::vector<ReceiverNode> nodes;   // the root first
    std::vector<uint32_t> patches;     // patch indices, each node's a contiguous range
};

// Throws std::invalid_argument for leafSize < 1. A node whose patches share one centre is a
// leaf whatever its size (no octant would split it).
ReceiverOctree buildReceiverOctree(std::span<const Aabb> patchBounds, uint32_t leafSize = 8);

}  // namespace shadowlab
