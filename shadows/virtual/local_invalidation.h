// Caching across frames for a spot or point light's mip chains (docs/virtual-shadow-
// maps.md; page_invalidation.h for the sun): a caster that moved changes only texels its
// silhouette covers from the light, which lie inside the perspective projection of its
// bounding box (before and after the move) into each face. Those pages are invalidated at
// every mip. A box that crosses the plane through the light facing a face has no bounded
// projection there (a beam may meet it on either side of the apex): the whole face is
// invalidated. A box wholly behind that plane touches no texel of the face. A light that
// moves changes every texel: the technique starts its table afresh (local_virtual_map.h).
#pragma once

#include <vector>

#include "scenes/bounds.h"
#include "shadows/virtual/mip_chain.h"
#include "shadows/virtual/page_invalidation.h"
#include "shadows/virtual/page_table.h"

namespace shadowlab::vsm {

// The pages of `level` under the box's projection ([x0, x1] x [y0, y1], clamped to the mip;
// x0 > x1 when none), all of them when the box crosses the face's light plane.
PageRange localPagesUnder(const Aabb& box, const MipChain& chain, int level);

// Invalidates the pages under each box at every level; returns how many valid pages it
// invalidated.
int invalidateLocalUnder(const std::vector<Aabb>& boxes, const MipChain& chain, PageTable& table);

}  // namespace shadowlab::vsm
