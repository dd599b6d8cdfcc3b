// Page marking for a spot or point light's mip chains (docs/virtual-shadow-maps.md;
// mip_chain.h): each pixel the light reaches takes the face whose pyramid holds it, and on
// it the mip whose texel matches its footprint, by the clipmap's rule (page_marking.h): the
// finest mip m whose texel, across the face's beam at the pixel's depth along the face's
// axis, 2 d tan(half-angle) 2^m / resolution, is no larger than the pixel's footprint times
// 2^lodBias (resolution-matched shadow maps, Lefohn et al. 2007). It marks every page under
// the texel box its lookup reads, [floor(u - reach), floor(u + reach)], clamped to the mip as
// the lookup clamps its texels (a shadow map's border, depth_map.h): a mip's window is the
// whole mip, so no pixel needs a coarser one. A pixel in no face (only the apex itself) is
// left unmarked and is lit.
#pragma once

#include <vector>

#include "scenes/scene.h"
#include "shading/gbuffer.h"
#include "shadows/virtual/mip_chain.h"
#include "shadows/virtual/page_marking.h"
#include "shadows/virtual/page_table.h"

namespace shadowlab::vsm {

// `light` decides which pixels it reaches (an area light as itself, shading/lights.h); the
// marked pages go into `table` (after its beginFrame with chain.windows()), each pixel's
// level (mip * faces + face) and texel coordinate into `levels`. Rows run in parallel; the
// result is the same for any thread count.
void markLocalPages(const GBuffer& g, const Camera& camera, const Light& light, const MipChain& chain,
                    const MarkingSettings& settings, PageTable& table, std::vector<PixelLevel>& levels);

// The finest mip whose texel at depth `along` (on the face's axis) is no larger than
// `footprint` * 2^lodBias, clamped to the chain's mips.
int matchingMip(const MipChain& chain, double footprint, double along, int lodBias);

// A receiver's texel coordinate in a level: the projection a DepthMap's lookup makes
// (shadow_bias.cpp), to the bit.
glm::dvec2 texelIn(const glm::dmat4& texelFromWorld, const glm::dvec3& P);

// The pages of `mip` under the texel box of half-width reach around `texel`, clamped to the
// mip's pages.
PageBox localPagesRead(const MipChain& chain, int mip, const glm::dvec2& texel, double reachTexels);

}  // namespace shadowlab::vsm
