#include "differential/source_tree.h"

#include <algorithm>
#include <numeric>

#include "scenes/bounds.h"

namespace shadowlab {
namespace {

int widestAxis(std::span<const uint32_t> patches, std::span<const Aabb> bounds) {
    glm::dvec3 lo(centre(bounds[patches[0]])), hi = lo;
    for (uint32_t p : patches) lo = glm::min(lo, centre(bounds[p])), hi = glm::max(hi, centre(bounds[p]));
    const glm::dvec3 extent = hi - lo;
    return extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
}

// Builds the subtree over `patches` (reordered in place) under `parent`; returns its index.
int32_t build(std::span<uint32_t> patches, int32_t parent, std::span<const Aabb> bounds, std::span<const double> transfer,
              SourceTree& tree) {
    const int32_t index = int32_t(tree.nodes.size());
    tree.nodes.push_back({bounds[patches[0]], parent, {-1, -1}, patches[0], 0.0});
    if (patches.size() == 1) {
        tree.nodes[index].transfer = transfer[patches[0]];
        tree.leafOfPatch[patches[0]] = index;
        return index;
    }
    const int axis = widestAxis(patches, bounds);
    const auto half = patches.begin() + patches.size() / 2;
    std::nth_element(patches.begin(), half, patches.end(), [&](uint32_t a, uint32_t b) {
        const double ca = centre(bounds[a])[axis], cb = centre(bounds[b])[axis];
        return ca < cb || (ca == cb && a < b);
    });
    const int32_t left = build(std::span(patches.begin(), half), index, bounds, transfer, tree);
    const int32_t right = build(std::span(half, patches.end()), index, bounds, transfer, tree);
    SourceNode& node = tree.nodes[index];
    node.children[0] = left, node.children[1] = right;
    node.bounds = merged(tree.nodes[left].bounds, tree.nodes[right].bounds);
    node.transfer = tree.nodes[left].transfer + tree.nodes[right].transfer;
    return index;
}

}  // namespace

SourceTree buildSourceTree(std::span<const Aabb> patchBounds, std::span<const double> transfer) {
    SourceTree tree;
    if (patchBounds.empty()) return tree;
    tree.nodes.reserve(2 * patchBounds.size() - 1);
    tree.leafOfPatch.assign(patchBounds.size(), -1);
    std::vector<uint32_t> patches(patchBounds.size());
    std::iota(patches.begin(), patches.end(), 0u);
    build(patches, -1, patchBounds, transfer, tree);
    return tree;
}

}  // namespace shadowlab
