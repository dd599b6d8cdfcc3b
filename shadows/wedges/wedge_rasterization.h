// The wedge pass (Assarsson and Akenine-Möller 2003, rendering the wedges with the pixel
// shader): a receiver point P inside a convex wedge lies on a view ray that enters the
// wedge in front of P and leaves it behind P. As the paper does, each wedge's front faces
// are drawn over the receivers' depth with the test Less, so a pixel gets a fragment of
// each wedge that begins in front of its P. That needs the ray to enter in front of the
// near plane: a wedge that may hold part of the near-plane rectangle (the eye within the
// rectangle's radius of all its planes, a test that can only err towards inside) has its
// back faces drawn instead, with the test GreaterEqual: where the ray leaves it, behind P.
// The fragments are listed per tile in drawing order (FragmentOutput::FragmentList); each
// pixel's P is then tested against the wedge's four planes and, inside, the edge's
// coverage (edge_coverage.h) is added to the pixel's sum. A wedge met twice at a pixel
// (at an edge two of its triangles share) counts once.
//
// One task per tile and a fixed order per pixel (the front-face draw's wedges in
// silhouette order, then the back-face draw's, then the edges without a wedge), so the
// sums are the same bytes for any thread count; the rasterizer's fragments are the same
// for every SIMD level, and this pass is scalar.
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
    bool inSpan;         // EdgeCoverage::inSpan
    double pSide;        // EdgeCoverage::pSide
};

struct WedgeCoverage {
    std::vector<double> correction;    // row-major: sum of coverage_e; V = V_hard - correction
    std::vector<NearCentre> nearCentre;   // in tile order, then per pixel in wedge order
    std::vector<float> wedgeCount;     // row-major: wedges holding P (plus the edges without one)
    uint64_t nearWedges = 0;           // wedges drawn by their back faces (near the near plane)
    uint64_t fillFragments = 0;        // the wedge faces' fragments before the depth test
    uint64_t listedFragments = 0;      // those that passed it
    uint64_t insideFragments = 0;      // those whose P is inside their wedge: coverage evaluated
};

// The silhouette edges and their world positions, as the wedges index them.
struct SilhouetteGeometry {
    std::span<const glm::vec3> positions;
    std::span<const SilhouetteEdge> edges;
};

// `fb` holds the receivers' depth drawn with clipFromWorld, the camera's, and has a
// fragment list.
WedgeCoverage rasterizeWedges(raster::Rasterizer& rasterizer, raster::Framebuffer& fb, const Camera& camera,
                              const glm::mat4& clipFromWorld, const WedgeSet& wedges,
                              const SilhouetteGeometry& silhouette, const AreaLightPlane& light, const GBuffer& g);

}  // namespace shadowlab
