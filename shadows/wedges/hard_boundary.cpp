#include "shadows/wedges/hard_boundary.h"

#include <algorithm>
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
            int x = 0, y = 0;
            raster::blockLinearPixel(f.pixel, fb.tilesX(), x, y);
            listed.emplace_back(size_t(y) * size_t(width) + size_t(x), f.primitiveId);
        }
    }
    std::sort(listed.begin(), listed.end());
    return listed;
}

// The sign of the plane through the edge and the light's centre at the eye.
double eyeSide(const ShadowInputs& in, const StencilPass& pass, uint32_t edge, const glm::dvec3& centre) {
    const SilhouetteEdge& e = pass.volume.silhouette[edge];
    const glm::dvec3 a(in.casterWorld().positions[e.from]), b(in.casterWorld().positions[e.to]);
    const double s = glm::dot(glm::cross(b - a, centre - a), glm::dvec3(in.camera().eye) - a);
    return s > 0.0 ? 1.0 : -1.0;
}

}  // namespace

uint64_t reconcileHardBoundary(raster::Rasterizer& rasterizer, raster::Framebuffer& fb, const ShadowInputs& in,
                               const StencilPass& pass, WedgeCoverage& coverage) {
    if (coverage.nearCentre.empty()) return 0;
    listSideFragments(rasterizer, fb, in, pass, edgesOf(coverage.nearCentre));
    const std::vector<std::pair<size_t, uint32_t>> listed = listedSides(fb, in.camera().width);
    const glm::dvec3 centre(in.light.position);
    uint64_t flipped = 0;
    for (const NearCentre& p : coverage.nearCentre) {
        const bool stencilFront = std::binary_search(listed.begin(), listed.end(), std::pair{p.pixel, p.edge});
        const bool geometryFront = eyeSide(in, pass, p.edge, centre) != -p.flip;
        if (stencilFront == geometryFront) continue;
        coverage.correction[p.pixel] += p.flip;
        ++flipped;
    }
    return flipped;
}

}  // namespace shadowlab
