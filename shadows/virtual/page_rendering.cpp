#include "shadows/virtual/page_rendering.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "scenes/camera.h"
#include "shadows/depth_map.h"

namespace shadowlab::vsm {
namespace {

// The box's square across the beam, in the frame's (x, y), m.
struct Footprint {
    glm::dvec2 lo, hi;
};
Footprint footprintOf(const Aabb& box, const LightFrame& frame) {
    Footprint f{glm::dvec2(INFINITY), glm::dvec2(-INFINITY)};
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec3 P{corner & 1 ? box.max.x : box.min.x, corner & 2 ? box.max.y : box.min.y,
                           corner & 4 ? box.max.z : box.min.z};
        const glm::dvec2 q(glm::dot(P, frame.x), glm::dot(P, frame.y));
        f.lo = glm::min(f.lo, q), f.hi = glm::max(f.hi, q);
    }
    return f;
}

// The page's square in the frame's (x, y): texel rows grow along -y.
Footprint pageSquare(const ClipmapSettings& clipmap, const PageKey& key) {
    const double side = clipmap.pageM(key.level);
    return {{key.x * side, -(key.y + 1) * side}, {(key.x + 1) * side, -key.y * side}};
}

// The triangles of the instances whose footprint meets the page, ascending, into `triangles`.
void pageCasters(const std::vector<InstanceRange>& ranges, const std::vector<Footprint>& footprints,
                 const Footprint& page, std::vector<uint32_t>& triangles) {
    triangles.clear();
    for (size_t i = 0; i < ranges.size(); ++i) {
        const Footprint& f = footprints[i];
        if (f.hi.x < page.lo.x || f.lo.x > page.hi.x || f.hi.y < page.lo.y || f.lo.y > page.hi.y) continue;
        for (uint32_t t = 0; t < ranges[i].triangleCount; ++t) triangles.push_back(ranges[i].firstTriangle + t);
    }
}

}  // namespace

DepthRange depthRangeOf(const std::vector<Aabb>& boxes, const LightFrame& frame) {
    double lo = INFINITY, hi = -INFINITY;
    for (const Aabb& box : boxes) {
        for (int corner = 0; corner < 8; ++corner) {
            const glm::dvec3 P{corner & 1 ? box.max.x : box.min.x, corner & 2 ? box.max.y : box.min.y,
                               corner & 4 ? box.max.z : box.min.z};
            const double distance = -glm::dot(P, frame.z);
            lo = std::min(lo, distance), hi = std::max(hi, distance);
        }
    }
    if (!(lo <= hi)) lo = hi = 0.0;   // no boxes
    const double pad = std::max(0.1 * (hi - lo), 0.01);
    return {lo - pad, hi + pad};
}

int cellTexels(const ClipmapSettings& clipmap) { return std::min(clipmap.resolution, raster::kMaxViewport); }

PageView pageView(const LightFrame& frame, const ClipmapSettings& clipmap, const DepthRange& range, const PageKey& key) {
    const int cell = cellTexels(clipmap), pagesPerCell = cell / clipmap.pageTexels;
    const auto cellOf = [&](int32_t page) { return page >= 0 ? page / pagesPerCell : -((-int64_t(page) - 1) / pagesPerCell) - 1; };
    const int64_t cx = cellOf(key.x), cy = cellOf(key.y);
    const double side = clipmap.texelM(key.level) * cell;
    PageView v;
    v.cell.orthographic = true;
    v.cell.viewFromWorld = glm::lookAtRH(glm::dvec3(0.0), -frame.z, lookAtUp(frame.z));
    v.cell.zNear = range.zNear, v.cell.zFar = range.zFar;
    v.cell.clipFromView = glm::orthoRH_NO(double(cx) * side, double(cx + 1) * side, -double(cy + 1) * side,
                                          -double(cy) * side, range.zNear, range.zFar);
    v.window = {cell, cell, int((int64_t(key.x) - cx * pagesPerCell) * clipmap.pageTexels),
                int((int64_t(key.y) - cy * pagesPerCell) * clipmap.pageTexels)};
    return v;
}

glm::dmat4 levelTexelFromWorld(const LightFrame& frame, const ClipmapSettings& clipmap, const DepthRange& range,
                               int level) {
    const double perM = 1.0 / clipmap.texelM(level), perDepth = 1.0 / (range.zFar - range.zNear);
    glm::dmat4 m(0.0);   // column-major: m[column][row]
    for (int c = 0; c < 3; ++c) {
        m[c][0] = frame.x[c] * perM;
        m[c][1] = -frame.y[c] * perM;
        m[c][2] = -frame.z[c] * perDepth;
    }
    m[3][2] = -range.zNear * perDepth;
    m[3][3] = 1.0;
    return m;
}

void drawPages(const PreparedScene& casters, std::span<const int32_t> physical, const PageSetup& setup,
               const raster::PolygonOffset& offset, raster::SimdLevel simd, PageDrawing& drawing, PagePool& pool) {
    if (physical.empty()) return;
    // The pool grows to the highest physical page drawn: memory only for pages in use.
    const size_t pageSize = size_t(pool.pageTexels) * size_t(pool.pageTexels);
    const size_t end = (size_t(*std::max_element(physical.begin(), physical.end())) + 1) * pageSize;
    if (pool.depth.size() < end) pool.depth.resize(end);
    drawing.drawers.resize(size_t(tbb::this_task_arena::max_concurrency()));
    tbb::parallel_for(size_t(0), physical.size(), [&](size_t k) {
        PageDrawer& d = drawing.drawers[size_t(tbb::this_task_arena::current_thread_index())];
        const PageView view = setup(k, d.triangles);
        tbb::this_task_arena::isolate([&] {
            d.map = renderDepthMap(casters.world(), d.triangles, view.cell,
                                   {pool.pageTexels, DepthLayer::First, offset, view.window}, simd, std::move(d.map),
                                   &d.rasterizer.at(simd));
            d.map.image(d.rows);
        });
        std::copy(d.rows.begin(), d.rows.end(), pool.depth.begin() + std::ptrdiff_t(size_t(physical[k]) * pageSize));
    });
}

void renderPages(const PreparedScene& casters, const std::vector<Aabb>& casterBoxes, const LightFrame& frame,
                 const ClipmapSettings& clipmap, const DepthRange& range, std::span<const PageKey> keys,
                 std::span<const int32_t> physical, const raster::PolygonOffset& offset, raster::SimdLevel simd,
                 PageDrawing& drawing, PagePool& pool) {
    if (keys.empty()) return;
    const std::vector<InstanceRange> ranges = instanceRanges(casters.scene());
    std::vector<Footprint> footprints;
    for (const Aabb& box : casterBoxes) footprints.push_back(footprintOf(box, frame));
    const auto setup = [&](size_t k, std::vector<uint32_t>& triangles) {
        pageCasters(ranges, footprints, pageSquare(clipmap, keys[k]), triangles);
        return pageView(frame, clipmap, range, keys[k]);
    };
    drawPages(casters, physical, setup, offset, simd, drawing, pool);
}

}  // namespace shadowlab::vsm
