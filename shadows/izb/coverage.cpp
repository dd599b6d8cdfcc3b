// Irregular z-buffer, stage 4: the texels an occluder must visit, i.e. every texel whose
// closed square its projection from the light touches (outer conservative rasterization;
// Aila and Laine 2004; RTR4 7.9: "conservative rasterization ensures that, even
// if a triangle does not cover the center of a light texel, it will be tested against points
// it may overlap").
//
// Why not raster/'s conservative mode: the framebuffer keeps one value per pixel, but a
// texel needs every triangle over it; and the fixed-point snapping there would move edges
// by up to half a sub-pixel, which only a dilation could answer for. Here the footprint is
// computed in double on the clipped polygon and widened by kSlack texels, which bounds the
// rounding of the projection (about 1e-12 texels for coordinates within 10^3 frustum widths
// of the light) by eight orders of magnitude. tests/shadows/izb/test_izb_structures.cpp checks
// it against a brute-force exact test.
#include <algorithm>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "shadows/izb/izb.h"

namespace shadowlab::izb {
namespace {

constexpr double kSlack = 1e-4;   // texels

// A half-space of clip space: dot(normal, c) + offset >= 0.
struct HalfSpace {
    glm::dvec4 normal;
    double offset;
    // How far inside c lies (negative outside): the one expression clipping and the
    // projected-vertex test (insideRegion) both decide by.
    double distance(const glm::dvec4& c) const { return glm::dot(normal, c) + offset; }
};

// Sutherland-Hodgman against one half-space.
int clipAgainst(const HalfSpace& h, const glm::dvec4* in, int n, glm::dvec4* out) {
    int m = 0;
    for (int i = 0; i < n; ++i) {
        const glm::dvec4 &a = in[i], &b = in[(i + 1) % n];
        const double da = h.distance(a), db = h.distance(b);
        if (da >= 0.0) out[m++] = a;
        // The crossing is interpolated from the inside end, as in raster/clip.cpp.
        if (da >= 0.0 && db < 0.0) out[m++] = a + (b - a) * (da / (da - db));
        if (da < 0.0 && db >= 0.0) out[m++] = b + (a - b) * (db / (db - da));
    }
    return m;
}

}  // namespace

// The triangle is clipped in homogeneous clip space to the view's sides widened by one
// texel (anything beyond cannot touch a texel of the grid) and, for a perspective view, to
// depth >= minDepth. The latter keeps x / w finite; it drops only points within a thousandth
// of the reference's offset of the light's plane, which the reference ignores too (its rays
// stop that far short of the light).
namespace {

struct ClipRegion {
    HalfSpace planes[5];
    int count;
};

ClipRegion clipRegion(const LightGrid& grid, int view) {
    const double side = 1.0 + 2.0 / grid.resolution;   // one texel, in normalised device units
    // |x|, |y| <= side * w; and w >= minDepth, since clip space w is the view depth of a
    // perspective view (glm::frustumRH_NO). An orthographic view has w = 1 everywhere.
    return {{{{-1, 0, 0, side}, 0.0}, {{1, 0, 0, side}, 0.0}, {{0, -1, 0, side}, 0.0}, {{0, 1, 0, side}, 0.0},
             {{0, 0, 0, 1}, -grid.minDepth}},
            grid.views[size_t(view)].orthographic ? 4 : 5};
}

glm::dvec4 clipPoint(const LightGrid& grid, int view, const glm::dvec3& p) {
    return grid.clipFromWorld[size_t(view)] * glm::dvec4(p, 1.0);
}

glm::dvec2 texelPoint(const glm::dvec4& c, int resolution) {
    return {(c.x / c.w + 1.0) * 0.5 * resolution, (1.0 - c.y / c.w) * 0.5 * resolution};
}

// Inside every half-space, by the test clipAgainst() makes.
bool insideRegion(const ClipRegion& region, const glm::dvec4& c) {
    for (int p = 0; p < region.count; ++p) {
        if (!(region.planes[p].distance(c) >= 0.0)) return false;
    }
    return true;
}

}  // namespace

LightPolygon projectOccluder(const LightGrid& grid, int view, const glm::dvec3 (&triangle)[3]) {
    const ClipRegion region = clipRegion(grid, view);
    glm::dvec4 polygon[8], next[8];
    for (int k = 0; k < 3; ++k) polygon[k] = clipPoint(grid, view, triangle[k]);
    int n = 3;
    for (int p = 0; p < region.count && n > 0; ++p) {
        n = clipAgainst(region.planes[p], polygon, n, next);
        std::copy(next, next + n, polygon);
    }
    LightPolygon out;
    out.count = n;
    for (int k = 0; k < n; ++k) out.vertex[k] = texelPoint(polygon[k], grid.resolution);
    return out;
}

ProjectedOccluders projectOccluders(const LightGrid& grid, const WorldGeometry& world) {
    const size_t vertices = world.positions.size();
    ProjectedOccluders out{world, vertices, std::vector<glm::dvec2>(grid.views.size() * vertices),
                           std::vector<uint8_t>(grid.views.size() * vertices)};
    for (int view = 0; view < int(grid.views.size()); ++view) {
        const ClipRegion region = clipRegion(grid, view);
        tbb::parallel_for(tbb::blocked_range<size_t>(0, vertices, 16384), [&](const auto& range) {
            for (size_t i = range.begin(); i != range.end(); ++i) {
                const glm::dvec4 c = clipPoint(grid, view, glm::dvec3(world.positions[i]));
                const size_t at = size_t(view) * vertices + i;
                out.inside[at] = insideRegion(region, c);
                if (out.inside[at]) out.texel[at] = texelPoint(c, grid.resolution);
            }
        });
    }
    return out;
}

// Clipping keeps a polygon wholly inside every half-space as it is, so such a triangle is
// its three projected corners: the polygon projectOccluder() returns, the same bits.
LightPolygon ProjectedOccluders::polygon(const LightGrid& grid, int view, uint32_t triangle) const {
    const glm::uvec3& corner = world.triangles[triangle];
    const size_t base = size_t(view) * vertexCount;
    if (!(inside[base + corner.x] && inside[base + corner.y] && inside[base + corner.z])) {
        return projectOccluder(grid, view, {glm::dvec3(world.positions[corner.x]), glm::dvec3(world.positions[corner.y]),
                                            glm::dvec3(world.positions[corner.z])});
    }
    LightPolygon out;
    out.count = 3;
    for (int k = 0; k < 3; ++k) out.vertex[k] = texel[base + corner[k]];
    return out;
}

TexelRange coveredRows(const LightPolygon& polygon, int resolution) {
    if (polygon.count == 0) return {};
    double lo = polygon.vertex[0].y, hi = lo;
    for (int k = 1; k < polygon.count; ++k) lo = std::min(lo, polygon.vertex[k].y), hi = std::max(hi, polygon.vertex[k].y);
    // Row j's closed band is [j, j + 1]: a polygon reaching v = j touches rows j - 1 and j.
    return {std::max(0, int(std::floor(lo - kSlack))), std::min(resolution, int(std::floor(hi + kSlack)) + 1)};
}

// A convex polygon's part inside the band has its extreme u on the polygon's edges, so the
// range is that of the edges clipped to the band.
TexelRange coveredColumns(const LightPolygon& polygon, double v0, double v1, int resolution) {
    const double lo = v0 - kSlack, hi = v1 + kSlack;
    double uMin = INFINITY, uMax = -INFINITY;
    for (int k = 0; k < polygon.count; ++k) {
        glm::dvec2 a = polygon.vertex[k], b = polygon.vertex[(k + 1) % polygon.count];
        if (a.y > b.y) std::swap(a, b);
        if (b.y < lo || a.y > hi) continue;
        const double dv = b.y - a.y;
        const double t0 = dv > 0.0 ? std::max(0.0, (lo - a.y) / dv) : 0.0;
        const double t1 = dv > 0.0 ? std::min(1.0, (hi - a.y) / dv) : 1.0;
        const double u0 = a.x + t0 * (b.x - a.x), u1 = a.x + t1 * (b.x - a.x);
        uMin = std::min({uMin, u0, u1}), uMax = std::max({uMax, u0, u1});
    }
    if (uMin > uMax) return {};
    return {std::max(0, int(std::floor(uMin - kSlack))), std::min(resolution, int(std::floor(uMax + kSlack)) + 1)};
}

}  // namespace shadowlab::izb
