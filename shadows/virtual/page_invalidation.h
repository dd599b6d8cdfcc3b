// Caching across frames (docs/virtual-shadow-maps.md): a page keeps its depth until
// something that could change it moves. A texel's depth is the nearest caster along the
// light's beam through it, so a caster can change only the texels its silhouette covers in
// the light's view, which lie inside the light-view projection of its bounding box. A caster
// that moved invalidates, at every level, the pages under the projections of its box before
// and after the move (Unreal Engine 5 invalidates a moving instance's pages the same way, by
// its bounds; Epic's "Virtual Shadow Maps" documentation, "Caching").
//
// A change of the light's direction changes every texel: the whole table is invalidated.
#pragma once

#include <vector>

#include "scenes/bounds.h"
#include "shadows/virtual/clipmap.h"
#include "shadows/virtual/page_table.h"

namespace shadowlab::vsm {

// The pages of `level` (global coordinates) whose texels the box's light-view projection
// touches: the projection's rectangle of the frame's (x, y), outward to whole texels.
struct PageRange {
    int32_t x0, y0, x1, y1;
};
PageRange pagesUnder(const Aabb& box, const LightFrame& frame, const ClipmapSettings& clipmap, int level);

// The boxes of the instances whose box changed from `last` to `now` (one per instance in
// both), before and after the move: what a virtual map invalidates under.
std::vector<Aabb> movedBoxes(const std::vector<Aabb>& last, const std::vector<Aabb>& now);

// Invalidates, at every level, the pages under each box (a moved caster's bounds before and
// after); returns how many valid pages it invalidated.
int invalidateUnder(const std::vector<Aabb>& boxes, const LightFrame& frame, const ClipmapSettings& clipmap,
                    PageTable& table);

}  // namespace shadowlab::vsm
