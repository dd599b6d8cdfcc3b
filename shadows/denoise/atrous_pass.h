// One pass of the edge-avoiding à-trous wavelet filter (Schied et al. 2017, SVGF, section
// 4.3; Dammertz et al. 2010): a 5x5 B3-spline kernel h whose taps lie `step` pixels apart
// (1, 2, 4, ... over the passes, so five passes reach 65 pixels with 25 taps each), every
// tap weighted by the edge-stopping functions (edge_stopping.h): eq. 1,
//   c'(p) = sum h(q) w(p, q) c(q) / sum h(q) w(p, q),
// and the variance carried to the next pass as the filtered signal's (eq. 2),
//   Var'(p) = sum h(q)^2 w(p, q)^2 Var(q) / (sum h(q) w(p, q))^2.
// The signal weight reads p's variance blurred by a 3x3 Gaussian first (section 4.3), which
// steadies an estimate from few samples.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "shading/gbuffer.h"
#include "shadows/denoise/edge_stopping.h"
#include "shadows/denoise/surface_features.h"

namespace shadowlab {

struct FilteredSignal {
    std::vector<float> value, variance;
};

// Filters `in` at `step` into `out` (resized). Where `filtered` is not empty, only its
// pixels marked 1 are filtered; the others keep their value and variance (the tiles a
// classification skips).
void atrousPass(const FilteredSignal& in, const GBuffer& gbuffer, const SurfaceFeatures& features,
                const EdgeStopping& edges, int step, std::span<const uint8_t> filtered, FilteredSignal& out);

}  // namespace shadowlab
