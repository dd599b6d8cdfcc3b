#include "shadows/virtual/page_rendering.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

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

void drawPage(const PreparedScene& casters, std::span<const uint32_t> triangles, const LightView& view,
              const raster::ViewportWindow& window, int32_t physical, const raster::PolygonOffset& offset,
              raster::SimdLevel simd, PageDrawing& drawing, PagePool& pool) {
    const size_t pageSize = size_t(pool.pageTexels) * size_t(pool.pageTexels);
    drawing.map = renderDepthMap(casters.world(), triangles, view, {pool.pageTexels, DepthLayer::First, offset, window},
                                 simd, std::move(drawing.map), &drawing.rasterizer.at(simd));
    drawing.map.image(drawing.rows);
    // The pool grows to the highest physical page drawn: memory only for pages in use.
    const size_t end = (size_t(physical) + 1) * pageSize;
    if (pool.depth.size() < end) pool.depth.resize(end);
    std::copy(drawing.rows.begin(), drawing.rows.end(), pool.depth.begin() + std::ptrdiff_t(size_t(physical) * pageSize));
}

void renderPages(const PreparedScene& casters, const std::vector<Aabb>& casterBoxes, const LightFrame& frame,
                 const ClipmapSettings& clipmap, const DepthRange& range, std::span<const PageKey> keys,
                 std::span<const int32_t> physical, const raster::PolygonOffset& offset, raster::SimdLevel simd,
                 PageDrawing& drawing, PagePool& pool) {
    if (keys.empty()) return;
    const std::vector<InstanceRange> ranges = instanceRanges(casters.scene());
    std::vector<Footprint> footprints;
    for (const Aabb& box : casterBoxes) footprints.push_back(footprintOf(box, frame));
    for (size_t k = 0; k < keys.size(); ++k) {
        pageCasters(ranges, footprints, pageSquare(clipmap, keys[k]), drawing.triangles);
        const PageView view = pageView(frame, clipmap, range, keys[k]);
        drawPage(casters, drawing.triangles, view.cell, view.window, physical[k], offset, simd, drawing, pool);
    }
}

}  // namespace shadowlab::vsm
