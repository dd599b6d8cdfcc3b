// The hard shadow's boundary, where the stencil and the wedges must agree. The stencil
// pass decides per pixel, by its float depth test, whether a volume side lies in front of
// the receiver point P; the edge's coverage (edge_coverage.h) decides in double on which
// side of the projected edge the light's centre lies, which is the same question. Where P
// is within rounding of the side, the two may answer differently, and V is then off by 1
// (a pixel of full light inside the shadow, or the reverse). The paper's
// formulation has the same seam between its hard shadow pass and its wedge pass.
//
// For each receiver point whose centre lies next to an edge (NearCentre), the edge's sides
// are drawn again with the stencil pass's own state (stencil_pass.h, listSideFragments),
// which tells per pixel what that pass decided; where it decided otherwise than the
// geometry, the edge's coverage is taken with the centre on the stencil's side (+ flip).
// The geometry's answer: the side is in front of P exactly when the eye E and P lie on
// opposite sides of the plane through the edge and the centre; P's side is -flip (the
// orientation edge_coverage.h's sigma and side give), E's the plane's sign at E.
#pragma once

#include <cstdint>
#include <vector>

#include "raster/rasterizer.h"
#include "shadows/technique.h"
#include "shadows/volumes/stencil_pass.h"
#include "shadows/wedges/wedge_rasterization.h"

namespace shadowlab {

// Adds the flips to coverage.correction; returns how many receiver points were flipped.
uint64_t reconcileHardBoundary(raster::Rasterizer& rasterizer, raster::Framebuffer& fb, const ShadowInputs& in,
                               const StencilPass& pass, WedgeCoverage& coverage);

}  // namespace shadowlab
