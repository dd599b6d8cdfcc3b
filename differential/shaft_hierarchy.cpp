#include "differential/shaft_hierarchy.h"

#include <algorithm>

namespace shadowlab {
namespace {

double diagonal(const Aabb& b) { return glm::length(b.max - b.min); }

// The paper's frame tags: a patch found through another shaft is not listed again.
struct TaggedList {
    std::vector<uint8_t> found;
    std::vector<uint32_t>& patches;
    void add(uint32_t patch) {
        if (!found[patch]) found[patch] = 1, patches.push_back(patch);
    }
};

struct ShaftBuilder {
    const SourceTree& sources;
    const ReceiverOctree& receivers;
    const ShaftSignificance& significant;
    ShaftHierarchy& out;

    void addChild(int32_t source, int32_t receiver) {
        if (!significant(source, receiver)) return;
        out.nodes.push_back({makeShaft(sources.nodes[source].bounds, receivers.nodes[receiver].bounds), source,
                             receiver, -1, 0});
    }

    // The children of shaft `index`: its larger non-leaf end split, the other end kept.
    void split(int32_t index) {
        const int32_t source = out.nodes[index].source, receiver = out.nodes[index].receiver;
        const SourceNode& s = sources.nodes[source];
        const ReceiverNode& r = receivers.nodes[receiver];
        if (s.leaf() && r.leaf()) return;
        const bool splitSource = r.leaf() || (!s.leaf() && diagonal(s.bounds) >= diagonal(r.bounds));
        const int32_t first = int32_t(out.nodes.size());
        if (splitSource) {
            for (int32_t child : s.children) addChild(child, receiver);
        } else {
            for (uint32_t c = 0; c < r.childCount; ++c) addChild(source, r.firstChild + int32_t(c));
        }
        const uint32_t count = uint32_t(out.nodes.size()) - uint32_t(first);
        // No child passes the 2% rule (section 6) on its own, but together they passed it
        // here: this shaft stays a leaf standing for all of them, or a light cut into dim
        // enough patches would be lost whole.
        if (count == 0) return;
        out.nodes[index].firstChild = first, out.nodes[index].childCount = count;
        for (uint32_t c = 0; c < count; ++c) split(first + int32_t(c));
    }
};

}  // namespace

size_t ShaftHierarchy::leafCount() const {
    return size_t(std::count_if(nodes.begin(), nodes.end(), [](const ShaftNode& n) { return n.leaf(); }));
}

ShaftHierarchy buildShaftHierarchy(const SourceTree& sources, const ReceiverOctree& receivers,
                                   const ShaftSignificance& significant) {
    ShaftHierarchy out;
    if (sources.nodes.empty() || receivers.nodes.empty()) return out;
    ShaftBuilder builder{sources, receivers, significant, out};
    builder.addChild(0, 0);
    if (!out.nodes.empty()) builder.split(0);
    return out;
}

ShaftHits traverseShafts(const ShaftHierarchy& shafts, const SourceTree& sources, const ReceiverOctree& receivers,
                         const Aabb& object) {
    ShaftHits hits;
    if (shafts.nodes.empty()) return hits;
    TaggedList sourceList{std::vector<uint8_t>(sources.leafOfPatch.size(), 0), hits.sourcePatches};
    TaggedList receiverList{std::vector<uint8_t>(receivers.patches.size(), 0), hits.receiverPatches};
    std::vector<int32_t> stack{0};
    while (!stack.empty()) {
        const int32_t index = stack.back();
        const ShaftNode& n = shafts.nodes[size_t(index)];
        stack.pop_back();
        if (!shaftMayTouch(n.shaft, object)) continue;
        if (!n.leaf()) {
            for (uint32_t c = n.childCount; c-- > 0;) stack.push_back(n.firstChild + int32_t(c));
            continue;
        }
        // Section 6.1 lists a leaf's source patch and receivers; a leaf above the source
        // tree's leaves lists every patch under its source node, as its pairs would.
        hits.leafShafts.push_back(index);
        forEachPatch(sources, n.source, [&](uint32_t patch) { sourceList.add(patch); });
        const ReceiverNode& r = receivers.nodes[n.receiver];
        for (uint32_t k = r.firstPatch; k < r.firstPatch + r.patchCount; ++k) receiverList.add(receivers.patches[k]);
    }
    return hits;
}

}  // namespace shadowlab
