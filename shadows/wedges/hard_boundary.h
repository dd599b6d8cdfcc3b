// The hard shadow's boundary, where the stencil and the wedges must agree. The stencil
// pass decides per pixel, by its float depth test, whether each volume side lies in front
// of the receiver point P; the edges' coverage (edge_coverage.h) decides in double on which
// side of each projected edge the light's centre lies, which is the same question. Where
// P is within rounding of a side, the two may answer differently, and V is then off by 1
// (a pixel of full light inside the shadow, or the reverse) or, at a silhouette vertex,
// by a corner's share. The paper's hard shadow pass and wedge pass share this seam.
//
// For each receiver point whose centre lies next to an edge (NearCentre), the edge's sides
// are drawn again with the stencil pass's own state (stencil_pass.h, listSideFragments),
// which tells what that pass decided at the pixel. The geometry's answer: the side is in
// front of P exactly when the centre is within the edge's span from P (inSpan) and the eye
// E and P lie on opposite sides of the plane through the edge and the centre (P's side is
// pSide, E's the plane's sign at E). Each side in front of P adds E's side to the count, so
// the exact count is the stencil's plus (geometry - stencil) E's side, and the edge's
// coverage takes that much more, keeping V = 1 - count - sum the geometry's. In the span
// this is the jump of coverage_e (the centre taken on the stencil's side); outside it, a
// count the neighbouring edge's side holds instead (at a silhouette vertex the two sides
// share a boundary, and the two differences cancel).
#pragma once

#include <cstdint>
#include <vector>

#include "raster/rasterizer.h"
#include "shadows/technique.h"
#include "shadows/volumes/stencil_pass.h"
#include "shadows/wedges/wedge_rasterization.h"

namespace shadowlab {

// Adds the differences to coverage.correction; returns how many (point, edge) pairs differed.
uint64_t reconcileHardBoundary(raster::Rasterizer& rasterizer, raster::Framebuffer& fb, const ShadowInputs& in,
                               const StencilPass& pass, WedgeCoverage& coverage);

}  // namespace shadowlab
