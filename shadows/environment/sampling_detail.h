// Sampling detail (DeCoro and Rusinkiewicz 2008, section 2.3): the shadow buffer S is
// computed at 1/k^2 of the pixels, from the same view seen by a camera k times smaller on
// each side, and resampled to full size (bilateral_upsample.h). The paper's levels are 1,
// 1/4, 1/16, ..., 1/1024 (k = 1, 2, 4, ..., 32).
#pragma once

#include <vector>

#include "scenes/scene.h"
#include "shadows/technique_params.h"

namespace shadowlab {

// The choices of the `sampling-detail` parameter: "1", "1/4", ..., "1/1024", read as k.
std::vector<Choice<int>> samplingDetailChoices();

// The camera of the same view with max(1, round(W / k)) x max(1, round(H / k)) pixels: the
// same eye, target, up and vertical field of view, so where k does not divide the size the
// sampled view is up to about one sampled pixel wider or narrower than the full one
// (bilateral_upsample.h maps between them and clamps its taps to the sampled image).
Camera sampledCamera(const Camera& camera, int k);

}  // namespace shadowlab
