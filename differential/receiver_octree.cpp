#include "differential/receiver_octree.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>

#include "scenes/bounds.h"

namespace shadowlab {
namespace {

Aabb boundsOf(std::span<const uint32_t> patches, std::span<const Aabb> bounds) {
    Aabb box = bounds[patches[0]];
    for (uint32_t p : patches) box = merged(box, bounds[p]);
    return box;
}

int octant(const glm::dvec3& c, const glm::dvec3& split) {
    return (c.x > split.x ? 1 : 0) | (c.y > split.y ? 2 : 0) | (c.z > split.z ? 4 : 0);
}

struct OctreeBuilder {
    std::span<const Aabb> bounds;
    uint32_t leafSize;
    ReceiverOctree& tree;

    // Splits node `index` into the octants of its patches' centres, recursively.
    void split(int32_t index) {
        const ReceiverNode node = tree.nodes[index];
        if (node.patchCount <= leafSize) return;
        const auto begin = tree.patches.begin() + node.firstPatch, end = begin + node.patchCount;
        // The middle of the patches' centres, not of their boxes: then only patches that
        // share one centre can fall into one octant.
        glm::dvec3 lo = centre(bounds[*begin]), hi = lo;
        for (auto p = begin; p != end; ++p) lo = glm::min(lo, centre(bounds[*p])), hi = glm::max(hi, centre(bounds[*p]));
        const glm::dvec3 middle = 0.5 * (lo + hi);
        // Patches ordered by octant (stable: by index within one), so each child is a range.
        std::stable_sort(begin, end, [&](uint32_t a, uint32_t b) {
            return octant(centre(bounds[a]), middle) < octant(centre(bounds[b]), middle);
        });
        if (octant(centre(bounds[*begin]), middle) == octant(centre(bounds[*(end - 1)]), middle)) return;   // one octant
        const int32_t firstChild = int32_t(tree.nodes.size());
        for (auto from = begin; from != end;) {
            const int o = octant(centre(bounds[*from]), middle);
            const auto to = std::find_if(from, end, [&](uint32_t p) { return octant(centre(bounds[p]), middle) != o; });
            const std::span<const uint32_t> patches(from, to);
            tree.nodes.push_back({boundsOf(patches, bounds), uint32_t(from - tree.patches.begin()), uint32_t(to - from), -1, 0});
            from = to;
        }
        tree.nodes[index].firstChild = firstChild;
        tree.nodes[index].childCount = uint32_t(tree.nodes.size()) - uint32_t(firstChild);
        for (uint32_t c = 0; c < tree.nodes[index].childCount; ++c) split(firstChild + int32_t(c));
    }
};

}  // namespace

ReceiverOctree buildReceiverOctree(std::span<const Aabb> patchBounds, uint32_t leafSize) {
    if (leafSize < 1) throw std::invalid_argument("receiver octree: the leaf size must be at least 1");
    ReceiverOctree tree;
    if (patchBounds.empty()) return tree;
    tree.patches.resize(patchBounds.size());
    std::iota(tree.patches.begin(), tree.patches.end(), 0u);
    tree.nodes.push_back({boundsOf(tree.patches, patchBounds), 0, uint32_t(patchBounds.size()), -1, 0});
    OctreeBuilder{patchBounds, leafSize, tree}.split(0);
    return tree;
}

}  // namespace shadowlab
