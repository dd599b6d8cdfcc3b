// The penumbra-driven spatial filter (penumbra.h): each pixel averages `taps` points of a
// disk of its own penumbra radius (penumbra_radius.h), laid on a golden-angle spiral
// (Vogel 1979) so that any count covers the disk evenly, weighted by a Gaussian of the
// distance (sigma: half the radius) and by SVGF's depth and normal edge-stopping functions
// (edge_stopping.h, eqs. 3, 4), so that the blur stays on the receiver. A radius under
// half a pixel leaves the pixel as it is: a hard shadow's edge comes through unchanged.
#pragma once

#include <span>
#include <vector>

#include "shading/gbuffer.h"
#include "shadows/denoise/edge_stopping.h"
#include "shadows/denoise/surface_features.h"

namespace shadowlab {

inline constexpr int kMaxPenumbraTaps = 128;

// Per G-buffer pixel (V where hit = 0). Throws std::invalid_argument for taps outside
// 1..kMaxPenumbraTaps.
std::vector<float> penumbraFilter(std::span<const float> visibility, const GBuffer& gbuffer,
                                  const SurfaceFeatures& features, std::span<const float> radius,
                                  const EdgeStopping& edges, int taps);

}  // namespace shadowlab
