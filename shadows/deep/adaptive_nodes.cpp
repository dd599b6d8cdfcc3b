#include "shadows/deep/adaptive_nodes.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadowlab {

void AdaptiveNodes::insert(float depth, float passed) {
    int at = count;
    while (at > 0 && nodes[at - 1].depth > depth) --at;
    const float inFront = at == 0 ? 1.0f : nodes[at - 1].transmittance;
    for (int k = count; k > at; --k) nodes[k] = {nodes[k - 1].depth, nodes[k - 1].transmittance * passed};
    nodes[at] = {depth, inFront * passed};
    if (++count > capacity) removeCheapest();
}

void AdaptiveNodes::removeCheapest() {
    int cheapest = 1;
    float least = std::numeric_limits<float>::infinity();
    for (int k = 1; k + 1 < count; ++k) {
        // Twice the area of the triangle the node makes with its neighbours.
        const CurveVertex a = nodes[k - 1], b = nodes[k], c = nodes[k + 1];
        const float area = std::abs((b.depth - a.depth) * (c.transmittance - a.transmittance) -
                                    (c.depth - a.depth) * (b.transmittance - a.transmittance));
        if (area < least) least = area, cheapest = k;
    }
    std::copy(nodes + cheapest + 1, nodes + count, nodes + cheapest);
    --count;
}

}  // namespace shadowlab
