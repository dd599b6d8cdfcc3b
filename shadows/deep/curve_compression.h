// Deep shadow maps' compression (Lokovic and Veach 2000, section 4.2): a texel's exact
// transmittance curve replaced by one with fewer vertices that stays within a tolerance
// epsilon of it everywhere. Greedy, in one pass front to back: from the last vertex placed,
// keep the range of slopes of lines that pass within epsilon of every input vertex so far;
// when the next vertex would empty the range, place a vertex on the middle line at the
// depth of the last input vertex that fitted, and start again from it. Both curves are
// linear between input vertices, so being within epsilon at the vertices is being within
// it everywhere. A vertical step that moves more than epsilon gets a vertex of its own.
#pragma once

#include <span>
#include <vector>

#include "shadows/deep/transmittance_curve.h"

namespace shadowlab {

// The compressed curve of `exact` into `out` (cleared first), within `tolerance` of it.
void compressCurve(std::span<const CurveVertex> exact, float tolerance, std::vector<CurveVertex>& out);

// The largest |compressed - exact| over the exact curve's vertices (tests, debug views).
float compressionError(std::span<const CurveVertex> exact, std::span<const CurveVertex> compressed);

}  // namespace shadowlab
