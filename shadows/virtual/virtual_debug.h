// The virtual shadow map's intermediate buffers (`--debug-buffers`, docs/virtual-shadow-
// maps.md): what marking chose per pixel and what the page table and pool hold.
//   level            per pixel, the level read (its index from the first, -1: none)
//   texels-per-pixel per pixel, the level's texels across the pixel's footprint (1: matched)
//   page-table       every level's table, one square of pagesPerSide^2 per level, stacked
//                    from the first level down, each page of the level's window:
//                    0 no memory, 0.125 evicted this frame (its memory given to another
//                    page), 0.25 memory but stale (invalidated), 0.5 valid but not read
//                    this frame, 0.75 read from the cache, 1 rendered this frame
//   pool             the physical pages in use as an atlas, page p at column p mod n, row
//                    p / n of an n x n grid, window depth
//   smrt-escaped     with shadow-map ray tracing, per pixel the fraction of its rays that
//                    went behind an occluder and escaped past its edge (smrt.h): where
//                    the depth history made the inner penumbra
// For a spot or point light's mip chains (mip_chain.h), in place of level and page-table
// (pool and smrt-escaped as above):
//   face             per pixel, the face read (0..5: kCubeFaceNames, 0 for a spot; -1: none)
//   mip              per pixel, the mip read (-1: none)
//   texels-per-pixel per pixel, the mip's texels across the pixel's footprint
//   page-table-face-<f>  (page-table for a spot's one face) every mip's table of the face,
//                    stacked from mip 0 down, each mip left-aligned in mip 0's width, the
//                    states as above
#pragma once

#include <vector>

#include "scenes/scene.h"
#include "shading/gbuffer.h"
#include "shadows/debug_buffers.h"
#include "shadows/virtual/mip_chain.h"
#include "shadows/virtual/page_marking.h"
#include "shadows/virtual/page_rendering.h"
#include "shadows/virtual/page_table.h"

namespace shadowlab::vsm {

// Written through `debug` (nothing when it is disabled); smrt-escaped only where
// escapedRays is not empty.
void writeVirtualDebug(const DebugBuffers& debug, const GBuffer& g, const Camera& camera,
                       const ClipmapSettings& clipmap, const std::vector<PixelLevel>& levels, const PageTable& table,
                       const std::vector<PageKey>& rendered, const PagePool& pool,
                       const std::vector<float>& escapedRays);
void writeLocalVirtualDebug(const DebugBuffers& debug, const GBuffer& g, const Camera& camera, const MipChain& chain,
                            const std::vector<PixelLevel>& levels, const PageTable& table,
                            const std::vector<PageKey>& rendered, const PagePool& pool,
                            const std::vector<float>& escapedRays);

}  // namespace shadowlab::vsm
