#include "shadows/wedges/wedge_rasterization.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <limits>

#include <tbb/parallel_for.h>

#include "shadows/volumes/counting_mode.h"

namespace shadowlab {
namespace {

constexpr uint32_t kNoWedge = std::numeric_limits<uint32_t>::max();

// Front faces in front of P, or (nearPlane) back faces behind it.
raster::PipelineState wedgePassState(bool nearPlane) {
    raster::PipelineState state;
    state.cull = nearPlane ? raster::CullMode::Front : raster::CullMode::Back;
    state.clipFar = false;
    state.depth = {.test = true, .write = false,
                   .func = nearPlane ? raster::CompareFunc::GreaterEqual : raster::CompareFunc::Less};
    state.output = raster::FragmentOutput::FragmentList;
    return state;
}

// The triangles of the wedges of one draw, each with its wedge's index as primitive id.
struct WedgeDraw {
    std::vector<glm::uvec3> triangles;
    std::vector<uint32_t> ids;
};

// Split by whether a wedge may hold part of the near-plane rectangle: every point of it is
// within `radius` of the eye, so one outside some plane by more is outside the wedge.
std::array<WedgeDraw, 2> splitByNearPlane(const WedgeSet& set, const glm::dvec3& eye, double radius) {
    std::array<WedgeDraw, 2> draws;
    for (uint32_t w = 0; w < set.wedges.size(); ++w) {
        bool near = true;
        for (const glm::dvec4& p : set.wedges[w].planes) near = near && glm::dot(glm::dvec3(p), eye) + p.w >= -radius;
        WedgeDraw& d = draws[near ? 1 : 0];
        for (uint32_t t = 0; t < kWedgeTriangles; ++t) {
            d.triangles.push_back(set.triangles[w * kWedgeTriangles + t]);
            d.ids.push_back(w);
        }
    }
    return draws;
}

// The largest distance from the eye to a corner of the near-plane rectangle (plus 1 mm).
double nearPlaneRadius(const Camera& camera) {
    double radius = 0.0;
    for (const glm::dvec3& c : nearPlaneCorners(camera)) {
        radius = std::max(radius, glm::length(c - glm::dvec3(camera.eye)));
    }
    return radius + 1e-3;
}

// Both draws into the fragment list; returns the wedges drawn by their back faces.
uint64_t drawWedges(raster::Rasterizer& rasterizer, raster::Framebuffer& fb, const Camera& camera,
                    const glm::mat4& clipFromWorld, const WedgeSet& set) {
    const std::array<WedgeDraw, 2> draws = splitByNearPlane(set, glm::dvec3(camera.eye), nearPlaneRadius(camera));
    fb.clearFragments();
    rasterizer.resetStats();
    for (int nearPlane = 0; nearPlane < 2; ++nearPlane) {
        raster::DrawCall call;
        call.vertices.homogeneousPositions = set.vertices;
        call.triangles = draws[nearPlane].triangles;
        call.primitiveIds = draws[nearPlane].ids;
        call.clipFromObject = clipFromWorld;
        if (!call.triangles.empty()) rasterizer.draw(fb, wedgePassState(nearPlane == 1), call);
    }
    return draws[1].ids.size() / kWedgeTriangles;
}

// Per-pixel state of the pass, row-major like the G-buffer.
struct PixelSums {
    std::vector<double> correction;
    std::vector<uint32_t> count, lastWedge;
};

class CoverageProgram {
public:
    CoverageProgram(const SilhouetteGeometry& silhouette, const AreaLightPlane& light, const GBuffer& g)
        : silhouette_(silhouette), light_(light), g_(g) {}

    EdgeCoverage coverage(uint32_t edge, size_t pixel) const {
        const SilhouetteEdge& e = silhouette_.edges[edge];
        return edgeCoverage(light_, glm::dvec3(g_.position[pixel]), glm::dvec3(silhouette_.positions[e.from]),
                            glm::dvec3(silhouette_.positions[e.to]));
    }

private:
    const SilhouetteGeometry& silhouette_;
    const AreaLightPlane& light_;
    const GBuffer& g_;
};

// The fragments of one tile, in order; returns how many were inside their wedge.
uint64_t shadeTile(const raster::Framebuffer& fb, int tile, const WedgeSet& set, const CoverageProgram& program,
                   const GBuffer& g, PixelSums& sums, std::vector<NearCentre>& nearCentre) {
    uint64_t inside = 0;
    for (const raster::Fragment& f : fb.tileFragments(tile)) {
        const size_t k = raster::rowMajorIndexOf(f.pixel, fb.tilesX(), g.width);
        const uint32_t w = f.primitiveId;
        if (!g.hit[k] || sums.lastWedge[k] == w) continue;
        sums.lastWedge[k] = w;
        const Wedge& wedge = set.wedges[w];
        if (!wedge.contains(glm::dvec3(g.position[k]))) continue;
        const EdgeCoverage c = program.coverage(wedge.edge, k);
        sums.correction[k] += c.coverage;
        if (c.nearCentre) nearCentre.push_back({k, wedge.edge, c.inSpan, c.pSide});
        ++sums.count[k], ++inside;
    }
    return inside;
}

// Edges without a wedge: every receiver point, after the wedges, rows in parallel.
void shadeUnbounded(const WedgeSet& set, const CoverageProgram& program, const GBuffer& g, PixelSums& sums,
                    std::vector<NearCentre>& nearCentre) {
    if (set.unboundedEdges.empty()) return;
    std::vector<std::vector<NearCentre>> perRow{size_t(g.height)};
    tbb::parallel_for(0, g.height, [&](int y) {
        for (size_t k = g.index(0, y); k < g.index(0, y + 1); ++k) {
            if (!g.hit[k]) continue;
            for (const uint32_t edge : set.unboundedEdges) {
                const EdgeCoverage c = program.coverage(edge, k);
                sums.correction[k] += c.coverage;
                if (c.nearCentre) perRow[size_t(y)].push_back({k, edge, c.inSpan, c.pSide});
            }
            sums.count[k] += uint32_t(set.unboundedEdges.size());
        }
    });
    for (const std::vector<NearCentre>& row : perRow) nearCentre.insert(nearCentre.end(), row.begin(), row.end());
}

}  // namespace

WedgeCoverage rasterizeWedges(raster::Rasterizer& rasterizer, raster::Framebuffer& fb, const Camera& camera,
                              const glm::mat4& clipFromWorld, const WedgeSet& wedges,
                              const SilhouetteGeometry& silhouette, const AreaLightPlane& light, const GBuffer& g) {
    WedgeCoverage out;
    out.nearWedges = drawWedges(rasterizer, fb, camera, clipFromWorld, wedges);
    out.fillFragments = rasterizer.stats().fragments;
    PixelSums sums{std::vector<double>(g.pixelCount(), 0.0), std::vector<uint32_t>(g.pixelCount(), 0),
                   std::vector<uint32_t>(g.pixelCount(), kNoWedge)};
    const CoverageProgram program(silhouette, light, g);
    std::atomic<uint64_t> inside = 0;
    const int tiles = fb.tilesX() * fb.tilesY();
    std::vector<std::vector<NearCentre>> perTile{size_t(tiles)};
    tbb::parallel_for(0, tiles, [&](int tile) {
        inside += shadeTile(fb, tile, wedges, program, g, sums, perTile[size_t(tile)]);
    });
    for (const std::vector<NearCentre>& t : perTile) out.nearCentre.insert(out.nearCentre.end(), t.begin(), t.end());
    shadeUnbounded(wedges, program, g, sums, out.nearCentre);
    for (int tile = 0; tile < tiles; ++tile) out.listedFragments += fb.tileFragments(tile).size();
    out.insideFragments = inside;
    out.correction = std::move(sums.correction);
    out.wedgeCount.assign(sums.count.begin(), sums.count.end());
    return out;
}

}  // namespace shadowlab
