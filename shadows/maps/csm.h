// The `csm` technique's two stages, for the technique and its tests: the cascades' maps
// (cascades.h fits them) and the selector that sends each receiver to its cascade.
#pragma once

#include <span>
#include <vector>

#include "raster/tile_kernels.h"
#include "scenes/bounds.h"
#include "scenes/prepared_scene.h"
#include "shadows/depth_map.h"
#include "shadows/kept_raster.h"
#include "shadows/maps/cascades.h"
#include "shadows/maps/shadow_lookup.h"

namespace shadowlab {

struct CascadedMaps {
    std::vector<Cascade> cascades;  // this frame's fit: its splits choose a receiver's cascade
    // One per cascade, each with the view it was drawn with (map.view, texelFromWorld), which
    // is an earlier frame's where stepped updates kept it; size 0 where it has no receivers.
    std::vector<DepthMap> maps;
    std::vector<uint8_t> drawnNow;  // per cascade: its map was drawn this frame
    uint64_t frame = 0;             // frames drawn into these maps: the stepped updates' clock
    glm::dvec3 towardsLight{0.0};   // the sun the maps were drawn for
    uint64_t geometryVersion = 0;   // the prepared scene's when casterBoxes were taken
    std::vector<Aabb> casterBoxes;  // per instance: where the casters were (movedCasters)
    KeptRasterizer rasterizer;      // what draws them, its buffers kept with the maps
};

// Stepped updates (as engines update far cascades less often, e.g. Unity HDRP's per-cascade
// RequestSubShadowMapRendering): with updateEvery = k, cascade 0 is drawn every frame and
// cascade i > 0 on the frames where (frame + i) % k == 0, staggered so that about one k-th
// of the far cascades is drawn a frame; the others keep their last map and the view it was
// drawn with, so a lookup lands where that map's casters were. A first frame, a sun that
// turned and a cascade without a map draw all that need one, and so does a cascade whose
// map a moved caster's bounds (before or after the move, `moved`) touch, unless the caller
// passes none: such a stale map would keep the caster where it was. A stale map covers the
// slice it had when drawn: a camera that moves far within k frames reads beyond it.
bool cascadeDue(const CascadedMaps& kept, size_t cascade, int updateEvery, std::span<const Aabb> moved);

// The boxes, before and after, of the casters whose box changed since `kept` last looked
// (the prepared scene's geometry version tells when to look); none on a first look.
std::vector<Aabb> movedCasters(const PreparedScene& casters, uint64_t geometryVersion, CascadedMaps& kept);

// The cascades' maps, drawn in `memory`'s (last frame's, when csm keeps them between frames:
// technique_history.h), reallocated only where a map grows; with updateEvery > 1, only the
// cascades due this frame (above).
CascadedMaps renderCascades(const Light& sun, const Camera& camera, const GBuffer& receivers, const WorldGeometry& world,
                            const CascadeSettings& cascades, const DepthMapSettings& maps, raster::SimdLevel simd,
                            CascadedMaps memory = {}, int updateEvery = 1, std::span<const Aabb> moved = {});

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
