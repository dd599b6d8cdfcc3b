// The source hierarchy of Gibson et al. 2003 (section 6): a binary kd-tree over the source
// patches, split top-down at the median of their centres along the widest axis until each
// leaf holds one patch ("a much deeper hierarchy than an octree", so that the number of
// shadow passes can be chosen one at a time, section 8). Each node keeps the box of its
// patches (a shaft's source end) and the sum of its patches' transfers.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "scenes/bounds.h"

namespace shadowlab {

struct SourceNode {
    Aabb bounds;
    int32_t parent = -1;              // -1 at the root
    int32_t children[2] = {-1, -1};   // -1, -1 at a leaf
    uint32_t patch = 0;               // a leaf's source patch (index into the inputs)
    double transfer = 0.0;            // the sum of its patches' (average) transfers
    bool leaf() const { return children[0] < 0; }
};

struct SourceTree {
    std::vector<SourceNode> nodes;    // the root first; 2 P - 1 nodes for P patches
    std::vector<int32_t> leafOfPatch; // patch -> its leaf
    double patchTransfer(uint32_t patch) const { return nodes[size_t(leafOfPatch[patch])].transfer; }
};

// One entry per source patch: its box (its centre is the split key) and its average transfer
// to the receivers. Deterministic: ties in the median split go by patch index.
SourceTree buildSourceTree(std::span<const Aabb> patchBounds, std::span<const double> transfer);

// Calls f(patch) for every patch under `node`, left to right.
template <class F>
void forEachPatch(const SourceTree& tree, int32_t node, const F& f) {
    const SourceNode& n = tree.nodes[size_t(node)];
    if (n.leaf()) return f(n.patch);
    for (const int32_t child : n.children) forEachPatch(tree, child, f);
}

}  // namespace shadowlab
