// The wedge pass (Assarsson and Akenine-Möller 2003, rendering the wedges with the pixel
// shader): every wedge's faces are drawn over the receivers' depth with the test
// GreaterEqual, so a pixel gets a fragment of a wedge whose faces lie behind (or at) its
// receiver point P. A P inside a convex wedge always has one, where the view ray leaves
// the wedge (faces are not culled, so this holds with the camera inside a wedge too; the
// cap at infinity closes the wedge at depth 1). The fragments are listed per tile in
// drawing order (FragmentOutput::FragmentList), i.e. per pixel in wedge order; each
// pixel's receiver point is then tested against the wedge's four planes and, inside, the
// edge's coverage (edge_coverage.h) is added to the pixel's sum. A wedge met twice at a
// pixel (two of its faces behind P) counts once.
//
// One task per tile and a fixed order per pixel (wedges in silhouette order, then the
// edges without a wedge), so the sums are the same bytes for any thread count; the
// rasterizer's fragments are the same for every SIMD level, and this pass is scalar.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "raster/rasterizer.h"
#include "shading/gbuffer.h"
#include "shadows/wedges/edge_coverage.h"
#include "shadows/wedges/wedge_construction.h"

namespace shadowlab {

// A receiver point whose light centre lies next to an edge's projection (EdgeCoverage::nearCentre).
struct NearCentre {
    size_t pixel;        // row-major
    uint32_t edge;       // silhouette index
    double flip;         // EdgeCoverage::flip
};

struct WedgeCoverage {
    std::vector<double> correction;    // row-major: sum of coverage_e; V = V_hard - correction
    std::vector<NearCentre> nearCentre;   // in tile order, then per pixel in wedge order
    std::vector<float> wedgeCount;     // row-major: wedges holding P (plus the edges without one)
    uint64_t fillFragments = 0;        // the wedge faces' fragments before the depth test
    uint64_t listedFragments = 0;      // those that passed it
    uint64_t insideFragments = 0;      // those whose P is inside their wedge: coverage evaluated
};

// The silhouette edges and their world positions, as the wedges index them.
struct SilhouetteGeometry {
    std::span<const glm::vec3> positions;
    std::span<const SilhouetteEdge> edges;
};

// `fb` holds the receivers' depth drawn with clipFromWorld and has a fragment list.
WedgeCoverage rasterizeWedges(raster::Rasterizer& rasterizer, raster::Framebuffer& fb, const glm::mat4& clipFromWorld,
                              const WedgeSet& wedges, const SilhouetteGeometry& silhouette, const CoverageLight& light,
                              const GBuffer& g);

}  // namespace shadowlab
