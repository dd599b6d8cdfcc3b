// Page rendering for a spot or point light's mip chains (docs/virtual-shadow-maps.md;
// page_rendering.h for the sun): each page to render is drawn as a window of its cell's
// perspective map, the off-centre part of its face's frustum that holds the cell's texels
// (MipChain::pageView), into its physical page, so its texels are that map's bits. Casters
// are culled per instance: an instance is drawn when its box's projection into the page's
// mip meets the page's texels, or, conservatively, when the box crosses the light's plane
// facing the face.
#pragma once

#include <span>
#include <vector>

#include "raster/pipeline_state.h"
#include "raster/tile_kernels.h"
#include "scenes/bounds.h"
#include "scenes/prepared_scene.h"
#include "shadows/virtual/mip_chain.h"
#include "shadows/virtual/page_rendering.h"

namespace shadowlab::vsm {

// Whether a box's projection may meet page `key`'s texels (its level's texelFromWorld given).
bool boxMeetsPage(const Aabb& box, const glm::dmat4& texelFromWorld, const PageKey& key, int pageTexels);

// Draws each page of `keys` into its physical page (physical[k] for keys[k]); `casterBoxes`
// are the casters' instances' boxes.
void renderLocalPages(const PreparedScene& casters, const std::vector<Aabb>& casterBoxes, const MipChain& chain,
                      std::span<const PageKey> keys, std::span<const int32_t> physical,
                      const raster::PolygonOffset& offset, raster::SimdLevel simd, PageDrawing& drawing, PagePool& pool);

}  // namespace shadowlab::vsm
