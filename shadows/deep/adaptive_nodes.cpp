#include "shadows/deep/adaptive_nodes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

namespace shadowlab {

void AdaptiveNodes::insertNode(int at, CurveVertex node) {
    std::copy_backward(nodes + at, nodes + count, nodes + count + 1);
    nodes[at] = node;
    ++count;
}

// The curve's value just behind depth z: behind every node at z (transmittanceAt gives the
// value in front of a step at z).
float AdaptiveNodes::behind(float z) const {
    int after = 0;
    while (after < count && nodes[after].depth <= z) ++after;
    if (after == 0) return 1.0f;
    if (after == count || nodes[after - 1].depth == z) return nodes[after - 1].transmittance;
    const CurveVertex a = nodes[after - 1], b = nodes[after];
    return a.transmittance + (z - a.depth) / (b.depth - a.depth) * (b.transmittance - a.transmittance);
}

void AdaptiveNodes::insertSegment(float entry, float exit, float passed) {
    const float inFront = transmittanceAt(std::span<const CurveVertex>(nodes, size_t(count)), entry);
    const float atExit = behind(exit);
    for (int k = 0; k < count; ++k) {
        CurveVertex& node = nodes[k];
        if (node.depth >= exit) {
            node.transmittance *= passed;
        } else if (node.depth > entry) {   // inside the segment: the share of it in front of the node
            const float share = (node.depth - entry) / (exit - entry);
            node.transmittance *= 1.0f + share * (passed - 1.0f);
        }
    }
    // The entry node goes before any node at its depth (the value in front of the step), the
    // exit node after every node up to its depth.
    int at = 0;
    while (at < count && nodes[at].depth < entry) ++at;
    insertNode(at, {entry, inFront});
    at = 0;
    while (at < count && nodes[at].depth <= exit) ++at;
    insertNode(at, {exit, atExit * passed});
    while (count > capacity) removeCheapest();
}

void AdaptiveNodes::removeCheapest() {
    int cheapest = 1;
    float least = std::numeric_limits<float>::infinity();
    for (int k = 1; k + 1 < count; ++k) {
        // Twice the area of the triangle the node makes with its neighbours: what the area
        // under the curve changes by without it.
        const CurveVertex a = nodes[k - 1], b = nodes[k], c = nodes[k + 1];
        const float area = std::abs((b.depth - a.depth) * (c.transmittance - a.transmittance) -
                                    (c.depth - a.depth) * (b.transmittance - a.transmittance));
        if (area < least) least = area, cheapest = k;
    }
    std::copy(nodes + cheapest + 1, nodes + count, nodes + cheapest);
    --count;
}

}  // namespace shadowlab
