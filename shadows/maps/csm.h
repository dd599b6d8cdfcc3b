// The `csm` technique's two stages, for the technique and its tests: the cascades' maps
// (cascades.h fits them) and the selector that sends each receiver to its cascade.
#pragma once

#include <vector>

#include "raster/tile_kernels.h"
#include "shadows/depth_map.h"
#include "shadows/kept_raster.h"
#include "shadows/maps/cascades.h"
#include "shadows/maps/shadow_lookup.h"

namespace shadowlab {

struct CascadedMaps {
    std::vector<Cascade> cascades;
    std::vector<DepthMap> maps;     // one per cascade; size 0 where it has no receivers
    KeptRasterizer rasterizer;      // what draws them, its buffers kept with the maps
};

// The cascades' maps, drawn in `memory`'s (last frame's, when csm keeps them between frames:
// technique_history.h), reallocated only where a map grows.
CascadedMaps renderCascades(const Light& sun, const Camera& camera, const GBuffer& receivers, const WorldGeometry& world,
                            const CascadeSettings& cascades, const DepthMapSettings& maps, raster::SimdLevel simd,
                            CascadedMaps memory = {});

// The map selector of cascades: the cascade by the receiver's distance along the camera's
// view axis, -1 where that cascade has no map.
struct CascadeSelector {
    const CascadedMaps& cascaded;
    const Camera& camera;
    int operator()(const glm::dvec3& P) const {
        const int k = cascadeOf(cascaded.cascades, viewDepth(camera, P));
        return cascaded.maps[k].size ? k : -1;
    }
};

}  // namespace shadowlab
