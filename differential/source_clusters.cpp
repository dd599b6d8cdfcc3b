#include "differential/source_clusters.h"

#include <algorithm>
#include <queue>
#include <stdexcept>
#include <string>

namespace shadowlab {
namespace {

// Figure 5b: per node, how many occluded patches lie under it (non-zero: marked) and the sum
// of their transfers, each occluded leaf walked up to the root once.
struct Marks {
    std::vector<uint32_t> count;
    std::vector<double> transfer;
};

Marks markOccluded(const SourceTree& tree, std::span<const uint32_t> occludedPatches) {
    Marks m{std::vector<uint32_t>(tree.nodes.size(), 0), std::vector<double>(tree.nodes.size(), 0.0)};
    for (uint32_t patch : occludedPatches) {
        if (patch >= tree.leafOfPatch.size())
            throw std::invalid_argument("representative sources: there is no source patch " + std::to_string(patch));
        const int32_t leaf = tree.leafOfPatch[patch];
        if (m.count[leaf]) continue;   // listed twice: the paper's frame tags keep it once
        for (int32_t node = leaf; node >= 0; node = tree.nodes[node].parent) {
            ++m.count[node];
            m.transfer[node] += tree.nodes[leaf].transfer;
        }
    }
    return m;
}

// A node with one marked child stands for the same occluded patches as that child: the
// list holds the lowest such node, the tightest cluster (its shadow map's view is fitted
// to the object from it, so a smaller cluster is a better point source).
int32_t tightest(const SourceTree& tree, const Marks& m, int32_t node) {
    while (!tree.nodes[node].leaf()) {
        const int32_t left = tree.nodes[node].children[0], right = tree.nodes[node].children[1];
        if (m.count[left] && m.count[right]) break;
        node = m.count[left] ? left : right;
    }
    return node;
}

void collectPatches(const SourceTree& tree, const Marks& m, int32_t node, std::vector<uint32_t>& out) {
    if (m.count[node] == 0) return;
    const SourceNode& n = tree.nodes[node];
    if (n.leaf()) return out.push_back(n.patch);
    for (int32_t child : n.children) collectPatches(tree, m, child, out);
}

}  // namespace

std::vector<SourceCluster> representativeSources(const SourceTree& tree, std::span<const uint32_t> occludedPatches, int n) {
    if (n < 1) throw std::invalid_argument("representative sources: n must be at least 1, got " + std::to_string(n));
    const Marks m = markOccluded(tree, occludedPatches);
    if (tree.nodes.empty() || m.count[0] == 0) return {};
    // Largest occluded transfer first; ties to the smaller node index, so the result is fixed.
    const auto before = [&](int32_t a, int32_t b) {
        return m.transfer[a] > m.transfer[b] || (m.transfer[a] == m.transfer[b] && a < b);
    };
    const auto after = [&](int32_t a, int32_t b) { return before(b, a); };
    std::priority_queue<int32_t, std::vector<int32_t>, decltype(after)> open(after);   // may still split
    std::vector<int32_t> listed;   // leaves: listed for good
    open.push(tightest(tree, m, 0));
    while (!open.empty() && open.size() + listed.size() < size_t(n)) {
        const int32_t node = open.top();
        open.pop();
        const SourceNode& s = tree.nodes[node];
        if (s.leaf()) {
            listed.push_back(node);
            continue;
        }
        for (int32_t child : s.children) {
            if (m.count[child]) open.push(tightest(tree, m, child));
        }
    }
    for (; !open.empty(); open.pop()) listed.push_back(open.top());
    std::sort(listed.begin(), listed.end(), before);
    std::vector<SourceCluster> clusters;
    for (int32_t node : listed) {
        SourceCluster c{node, m.transfer[node], {}};
        collectPatches(tree, m, node, c.patches);
        std::sort(c.patches.begin(), c.patches.end());
        clusters.push_back(std::move(c));
    }
    return clusters;
}

}  // namespace shadowlab
