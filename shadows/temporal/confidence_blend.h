// The history update of Scherzer et al. 2007 (section 4): each frame's shadow test s enters
// the reprojected history h at the weight its confidence c gives it (shadow_test_confidence.h),
//
//     h' = h + c^m (s - h),
//
// so a test made near a texel's centre (c near 1) counts, one near its side barely does; the
// exponent m trades how fast the history follows for how sharp it gets. A pixel whose history
// the reprojection rejected, and a sequence's first frame, takes s as it is.
#pragma once

#include <span>
#include <vector>

#include "shading/gbuffer.h"
#include "shadows/temporal/reprojection.h"

namespace shadowlab {

// `after` (resized to the G-buffer) from this frame's tests and confidences and the history
// `before` (indexed as the previous view), reprojected by `reprojection` (null: none).
void blendByConfidence(std::span<const float> tests, std::span<const float> confidence, double exponent,
                       const GBuffer& g, const Reprojection* reprojection, std::span<const float> before,
                       std::vector<float>& after);

}  // namespace shadowlab
