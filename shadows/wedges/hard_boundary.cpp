#include "shadows/wedges/hard_boundary.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace shadowlab {
namespace {

// The edges of the pairs, each once, in increasing order.
std::vector<uint32_t> edgesOf(const std::vector<NearCentre>& pairs) {
    std::vector<uint32_t> edges;
    for (const NearCentre& p : pairs) edges.push_back(p.edge);
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    return edges;
}

// (row-major pixel, edge) of every listed fragment, sorted for lookup.
std::vector<std::pair<size_t, uint32_t>> listedSides(const raster::Framebuffer& fb, int width) {
    std::vector<std::pair<size_t, uint32_t>> listed;
    for (int tile = 0; tile < fb.tilesX() * fb.tilesY(); ++tile) {
        for (const raster::Fragment& f : fb.tileFragments(tile)) {
            listed.emplace_back(raster::rowMajorIndexOf(f.pixel, fb.tilesX(), width), f.primitiveId);
        }
    }
    std::sort(listed.begin(), listed.end());
    return listed;
}

// The sign of the plane through the edge and the light's centre at the eye; 0 when the eye
// lies in it (to 1e-6 of its distance), where the side is seen edge on: no view ray
// crosses it and the rasterizer draws none of it.
double eyeSide(const ShadowInputs& in, const StencilPass& pass, uint32_t edge, const glm::dvec3& centre) {
    const SilhouetteEdge& e = pass.volume.silhouette[edge];
    const glm::dvec3 a(in.casterWorld().positions[e.from]), b(in.casterWorld().positions[e.to]);
    const glm::dvec3 n = glm::cross(b - a, centre - a), toEye = glm::dvec3(in.camera().eye) - a;
    const double s = glm::dot(n, toEye);
    if (!(std::abs(s) > 1e-6 * glm::length(n) * glm::length(toEye))) return 0.0;
    return s > 0.0 ? 1.0 : -1.0;
}

}  // namespace

uint64_t reconcileHardBoundary(raster::Rasterizer& rasterizer, raster::Framebuffer& fb, const ShadowInputs& in,
                               const StencilPass& pass, WedgeCoverage& coverage) {
    if (coverage.nearCentre.empty()) return 0;
    listSideFragments(rasterizer, fb, pass, edgesOf(coverage.nearCentre));
    const std::vector<std::pair<size_t, uint32_t>> listed = listedSides(fb, in.camera().width);
    const glm::dvec3 centre(in.light.position);
    uint64_t flipped = 0;
    for (const NearCentre& p : coverage.nearCentre) {
        const bool stencilFront = std::binary_search(listed.begin(), listed.end(), std::pair{p.pixel, p.edge});
        const double eye = eyeSide(in, pass, p.edge, centre);
        const bool geometryFront = p.inSpan && eye != 0.0 && eye != p.pSide;
        if (stencilFront == geometryFront) continue;
        coverage.correction[p.pixel] += eye * (double(geometryFront) - double(stencilFront));
        ++flipped;
    }
    return flipped;
}

}  // namespace shadowlab
