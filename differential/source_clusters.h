// The representative source set of Gibson et al. 2003 (section 8, Figures 5 and 6): when the
// shaft traversal finds more potentially occluded source patches than the frame has shadow
// passes for, n nodes of the source hierarchy stand for all of them. The occluded patches'
// leaves are marked up to the root (Figure 5b); then, from the root, the listed node with
// the largest occluded transfer is replaced by its marked children until n nodes are listed
// (Figure 6); a node with one marked child is listed as the lowest node below it that has
// the same occluded patches. Every occluded patch lies under exactly one listed node, so no
// occluded energy is lost: a cluster's shadow pass takes off the transfers of all its
// occluded patches (and only theirs).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "differential/source_tree.h"

namespace shadowlab {

struct SourceCluster {
    int32_t node;                    // in SourceTree::nodes
    double transfer;                 // the sum of its occluded patches' transfers
    std::vector<uint32_t> patches;   // its occluded patches, in patch order
};

// At most n clusters (n >= 1) covering the occluded patches (each listed once), in order
// of decreasing transfer, ties by node index; none if no patch is occluded. Throws
// std::invalid_argument for n < 1 or a patch the tree does not have.
std::vector<SourceCluster> representativeSources(const SourceTree& tree, std::span<const uint32_t> occludedPatches, int n);

}  // namespace shadowlab
