#include "differential/source_set.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

namespace shadowlab {

std::vector<uint32_t> selectSources(std::span<const EmittingPatch> patches, double share) {
    if (!(share > 0.0 && share <= 1.0)) throw std::invalid_argument("source set: the share of power must be in (0, 1]");
    double total = 0.0;
    for (size_t p = 0; p < patches.size(); ++p) {
        const EmittingPatch& e = patches[p];
        if (!(e.radiance >= 0.0 && std::isfinite(e.radiance) && e.area >= 0.0 && std::isfinite(e.area)))
            throw std::invalid_argument("source set: patch " + std::to_string(p) + " has a negative or non-finite radiance or area");
        total += e.radiance * e.area;   // pi L A, less the common factor pi
    }
    std::vector<uint32_t> order(patches.size());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return patches[a].radiance > patches[b].radiance; });
    std::vector<uint32_t> sources;
    double power = 0.0;
    for (uint32_t p : order) {
        if (patches[p].radiance * patches[p].area == 0.0) break;
        // Past the share, only patches as bright as the last taken: a light of one radiance whole.
        if (power >= share * total && patches[p].radiance < patches[sources.back()].radiance) break;
        sources.push_back(p);
        power += patches[p].radiance * patches[p].area;
    }
    return sources;
}

}  // namespace shadowlab
