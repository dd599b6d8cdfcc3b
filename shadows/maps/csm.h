// The `csm` technique's two stages, for the technique and its tests: the cascades' maps
// (cascades.h fits them) and the selector that sends each receiver to its cascade.
#pragma once

#include <vector>

#include "raster/tile_kernels.h"
#include "shadows/depth_map.h"
#include "shadows/maps/cascades.h"
#include "shadows/maps/shadow_lookup.h"

namespace shadowlab {

struct CascadedMaps {
    std::vector<Cascade> cascades;
    std::vector<DepthMap> maps;     // one per cascade; size 0 where it has no receivers
};

CascadedMaps renderCascades(const Light& sun, const Camera& camera, const GBuffer& receivers, const WorldGeometry& world,
                            const CascadeSettings& cascades, const DepthMapSettings& maps, raster::SimdLevel simd);

// Picks the cascade by the receiver's distance along the camera's view axis.
MapSelector cascadeSelector(const CascadedMaps& cascaded, const Camera& camera);

}  // namespace shadowlab
