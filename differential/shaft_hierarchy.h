// The shaft hierarchy of Gibson et al. 2003 (section 6) and its traversal (section 6.1):
// shafts between nodes of the source tree and the receiver octree, from the roots down,
// each split on the side whose box is larger (a leaf is never split) until both ends are
// leaves; a shaft whose transfer the caller deems insignificant (the paper's 2% rule) is
// not kept, nor anything below it. A kept shaft none of whose children is kept is a leaf
// and stands for every pair below it, so a light cut into patches too dim to pass one by
// one is still listed where it passes whole (docs/differential-rendering.md, "The
// significance rule"). Per frame, the shafts a synthetic object's box may touch give the
// sources it may occlude and the receivers that may see it happen. A parent's shaft holds
// its children's (differential/shaft.h), so the traversal stops at the first
// shaft the box misses.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "differential/receiver_octree.h"
#include "differential/shaft.h"
#include "differential/source_tree.h"

namespace shadowlab {

struct ShaftNode {
    Shaft shaft;
    int32_t source = 0, receiver = 0;   // nodes of the two hierarchies
    int32_t firstChild = -1;            // -1 at a leaf; else childCount shafts from here
    uint32_t childCount = 0;
    bool leaf() const { return firstChild < 0; }
};

struct ShaftHierarchy {
    std::vector<ShaftNode> nodes;   // the root first; empty if no transfer is significant
    size_t leafCount() const;       // shafts without children, each listing its two nodes' patches
};

// Whether to keep the shaft from a source node's patches to a receiver node's vertices
// (Gibson et al.: some vertex gets 2% of its light through it or more). Called once per
// shaft, in a fixed order (a shaft's children in turn, then each child's), so that a caller
// may keep account of the light it leaves out (preprocess.cpp).
using ShaftSignificance = std::function<bool(int32_t sourceNode, int32_t receiverNode)>;

ShaftHierarchy buildShaftHierarchy(const SourceTree& sources, const ReceiverOctree& receivers,
                                   const ShaftSignificance& significant);

// The sources (patch indices, each once, in the order found) and the receiver patches of
// the leaf shafts the box may touch, every patch under each end of such a shaft, and those
// shafts (indices into ShaftHierarchy::nodes, for the debug views).
struct ShaftHits {
    std::vector<uint32_t> sourcePatches;
    std::vector<uint32_t> receiverPatches;
    std::vector<int32_t> leafShafts;
};
ShaftHits traverseShafts(const ShaftHierarchy& shafts, const SourceTree& sources, const ReceiverOctree& receivers,
                         const Aabb& object);

}  // namespace shadowlab
