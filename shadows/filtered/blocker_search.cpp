#include "shadows/filtered/blocker_search.h"

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

}  // namespace shadowlab
