// Resampling the shadow buffer S to full size, S' (DeCoro and Rusinkiewicz 2008, section 2.3,
// step 4): a joint bilateral filter guided by the full-resolution G-buffer. For an output
// pixel p, the sampled pixels q of the 4 x 4 block whose centres are nearest p's centre (in
// the sampled image's pixel coordinates) are weighed by the paper's
//
//     w(p, q) = Gaussian(|P_p - P_q|) * max(0, Ns_p . Ns_q),
//
// a Gaussian of the distance between their world positions, of standard deviation sigma_p =
// k times the footprint of one full-size pixel at p (2 |P_p - eye| tan(fovy / 2) / H: the
// width of one sampled pixel there, so the filter reaches as far as the samples are apart,
// at any depth), times the agreement of their shading normals, clamped at 0 so that a
// surface facing away never lends its shadow. S'_p = sum w S_q / sum w. The block is
// found in the sampled image's pixels: both cameras share the vertical field of view, so
// the views are centred on each other at H_s / H sampled pixels per pixel on both axes
// (sampling_detail.h rounds the sizes, so the sampled view may be up to about one sampled
// pixel wider or narrower; taps are clamped to it).
//
// At sampling detail 1 there is nothing to resample: S' = S exactly. Where every weight is 0
// (a thin feature whose samples all lie on other surfaces) S'_p takes the hit sample nearest
// p in world space; with no hit sample among the 16, S'_p = 0. Both are counted.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/scene.h"
#include "shading/gbuffer.h"

namespace shadowlab {

struct UpsampleCounts {
    uint64_t nearestPixels = 0;   // every weight 0: the nearest hit sample taken
    uint64_t emptyPixels = 0;     // no hit sample in the block: S' = 0
};

// `full` and `sampled` are G-buffers of the same view (sampled by sampledCamera(camera, k));
// S has one entry per pixel of `sampled`. Returns S' with one entry per pixel of `full`, 0
// where full.hit = 0. The same bytes for any number of threads.
std::vector<glm::vec3> upsampleShadowBuffer(const GBuffer& full, const Camera& camera, const GBuffer& sampled,
                                            const std::vector<glm::vec3>& S, UpsampleCounts* counts = nullptr);

}  // namespace shadowlab
