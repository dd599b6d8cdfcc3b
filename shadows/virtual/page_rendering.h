// Page rendering (docs/virtual-shadow-maps.md): each page that marking requested and that
// holds no current depth is drawn by the rasterizer, pageTexels a side, as a window of its
// cell's map: an ordinary orthographic shadow map of the level's texels over a square of
// the light's frame (the depth range every page of the light shares), of which the page's
// texels are a part (raster/pipeline_state.h, ViewportWindow). Its depths are then the
// bits that ordinary map has there, drawn whole, and never depend on which other pages
// exist. Only the casters whose bounds' projection meets the page are drawn (Unreal Engine
// 5 culls instances per page the same way). The depths go into the page's place in the
// physical pool.
#pragma once

#include <functional>
#include <span>
#include <vector>

#include "raster/pipeline_state.h"
#include "raster/tile_kernels.h"
#include "scenes/bounds.h"
#include "scenes/prepared_scene.h"
#include "shadows/depth_map.h"
#include "shadows/kept_raster.h"
#include "shadows/light_view.h"
#include "shadows/virtual/clipmap.h"

namespace shadowlab::vsm {

// The light's depth range, shared by every page: distances along the beam (-z of the
// frame) that hold every caster and receiver of the world.
struct DepthRange {
    double zNear = 0.0, zFar = 1.0;
    bool holds(const DepthRange& r) const { return r.zNear >= zNear && r.zFar <= zFar; }
};
// The world's boxes' range, widened by 10 % of its length on each side (and at least 1 cm),
// so that a caster that moves a little keeps it and the pages it did not touch.
DepthRange depthRangeOf(const std::vector<Aabb>& boxes, const LightFrame& frame);

// A level's cells: squares of cellTexels() texels a side, min(resolution, the rasterizer's
// largest viewport), fixed in the light's frame (cell (0, 0) has its top-left corner at the
// frame's origin, rows down along -y, as pages). A cell is a whole number of pages, so a
// page lies in one cell.
int cellTexels(const ClipmapSettings& clipmap);
// How page `key` is drawn: its cell's orthographic view (window depth (distance - zNear) /
// (zFar - zNear)) and where the page lies in that view's viewport.
struct PageView {
    LightView cell;
    raster::ViewportWindow window;
};
PageView pageView(const LightFrame& frame, const ClipmapSettings& clipmap, const DepthRange& range, const PageKey& key);
// Level l as one huge map: world -> (global texel x, y, window depth, 1), the matrix every
// lookup of the level maps receivers with (a DepthMap's texelFromWorld, depth_map.h).
glm::dmat4 levelTexelFromWorld(const LightFrame& frame, const ClipmapSettings& clipmap, const DepthRange& range,
                               int level);

// The physical pool's depths: page p's texels, row-major, at p * pageTexels^2; it holds the
// pages up to the highest one drawn so far (the table hands out low pages first).
struct PagePool {
    int pageTexels = 0;
    std::vector<float> depth;
    float at(int32_t page, int x, int y) const {
        return depth[(size_t(page) * size_t(pageTexels) + size_t(y)) * size_t(pageTexels) + size_t(x)];
    }
};

// What drawing pages keeps from frame to frame (technique_history.h): per worker thread,
// the map a page is drawn in, a rasterizer, a page's casters and its rows.
struct PageDrawer {
    DepthMap map;
    KeptRasterizer rasterizer;
    std::vector<uint32_t> triangles;
    std::vector<float> rows;
};
struct PageDrawing {
    std::vector<PageDrawer> drawers;   // one per thread of the task arena
};

// How page k is drawn: its casters' triangles (ascending, into `triangles`) and its view.
// Called once per page, from any thread.
using PageSetup = std::function<PageView(size_t k, std::vector<uint32_t>& triangles)>;

// Draws pages 0 .. physical.size() - 1, page k into physical page physical[k], as a page of
// pool.pageTexels texels a side, growing the pool to hold them: the draw every page of any
// light's virtual map makes. Pages are drawn in parallel, each by one thread with its own
// drawer (its rasterizer's own parallel work isolated, so that no thread takes up a second
// page with the same drawer); a page's bits depend on its view and window alone, so the
// pool is the same for any thread count.
void drawPages(const PreparedScene& casters, std::span<const int32_t> physical, const PageSetup& setup,
               const raster::PolygonOffset& offset, raster::SimdLevel simd, PageDrawing& drawing, PagePool& pool);

// Draws each page of `keys` into its physical page (physical[k] for keys[k]); `casterBoxes`
// are the casters' instances' boxes, whose triangles are culled per page.
void renderPages(const PreparedScene& casters, const std::vector<Aabb>& casterBoxes, const LightFrame& frame,
                 const ClipmapSettings& clipmap, const DepthRange& range, std::span<const PageKey> keys,
                 std::span<const int32_t> physical, const raster::PolygonOffset& offset, raster::SimdLevel simd,
                 PageDrawing& drawing, PagePool& pool);

}  // namespace shadowlab::vsm
