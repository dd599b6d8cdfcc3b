#include "shadows/filtered/blocker_search.h"

#include <algorithm>
#include <cmath>

#include "raster/portable_math.h"
#include "shadows/maps/pcf.h"

namespace shadowlab {

const SettingsTable<BlockerSearchSettings>& blockerSearchSettingsTable() {
    using S = BlockerSearchSettings;
    static const auto table =
        SettingsTable<S>()
            .integer("search-taps", member(&S::taps), 1, 64, "blocker search: Poisson taps")
            .real("search-region", member(&S::region), 1e-3, 1.0,
                  "blocker search: fraction of the light's cone cut at the near plane");
    return table;
}

MapReceiver planeReceiver(const SoftShadowMap& soft, const glm::dvec3& P, const glm::dvec3& N) {
    BiasSettings bias;
    bias.mode = BiasMode::ReceiverPlane;
    return mapReceiverFromPoint(soft.map, P, N, soft.lightCentre, bias);
}

PenumbraEstimate estimatePenumbra(const SoftShadowMap& soft, const MapReceiver& r, double dr,
                                  const BlockerSearchSettings& settings, const std::vector<glm::dvec2>& disk,
                                  uint64_t pixel) {
    // A receiver nearer than the near plane cannot be shadowed: nothing lies in front of it.
    if (!(dr > soft.zNear())) return {};
    const glm::dvec2 radius = 0.5 * settings.region * sampleWidthTexels(soft, dr, soft.zNear());
    const double angle = poissonRotation(pixel);
    const glm::dvec2 rotation(portable::cos(angle), portable::sin(angle));
    PenumbraEstimate e;
    double distanceSum = 0.0;   // in tap order: the same sum for any thread count
    for (const glm::dvec2& d : disk) {
        const glm::dvec2 at = r.texel + rotatedTap(d, rotation, radius);
        const int x = texelIndexOf(at.x), y = texelIndexOf(at.y);
        if (r.litBy(soft.map, x, y)) continue;
        ++e.blockers;
        distanceSum += soft.distanceOf(soft.map.at(x, y));
    }
    if (e.blockers == 0) return e;
    // The polygon offset and the receiver plane can put a blocker's mean at or behind the
    // receiver by a rounding; clamp to the near plane .. receiver (width 0 at contact).
    e.blockerDistance = std::clamp(distanceSum / e.blockers, soft.zNear(), dr);
    e.widthTexels = sampleWidthTexels(soft, dr, e.blockerDistance);
    return e;
}

}  // namespace shadowlab
