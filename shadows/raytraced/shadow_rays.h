// Ray-traced shadows' one stage: N rays per pixel from each G-buffer point towards the
// light, through the exact reference's BVH, ray offset, cut-outs and translucent casters
// (shadows/reference/scene_rays.h), traced for their first occluders. Towards a point or
// spot light, or a point-like sun, a pixel's N rays would be N copies of one ray: one is
// traced, and V is 0 or 1 (the `reference` answer). Towards a disk, a rectangle or a sun
// with an angular size, the N rays go to the pixel's N samples of the light's area for this
// frame (shading/pixel_sequence.h), mapped as the soft reference maps its strata
// (shading/light_sampling.h): V is a noisy estimate of the visible fraction that the next
// frame's samples estimate again, which is what a temporal filter or a denoiser averages.
//
// Beside V it returns what a denoiser reads: the distance from P to the first occluder,
// averaged over the pixel's occluded rays, and the light's angular size from P, from which
// SIGMA's documented penumbra input is made (NVIDIA's NRD README: IN_PENUMBRA, the distance
// times the tangent of the light's angular radius, halved); how many rays were occluded
// (at one ray per pixel, the hit mask AMD FidelityFX's shadow denoiser documents as its
// input).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/scene.h"
#include "shading/gbuffer.h"
#include "shadows/progress.h"
#include "shadows/reference/reference.h"

namespace shadowlab {

struct ShadowRayBuffers {
    // Per pixel, row-major, 0 where the G-buffer has no surface:
    std::vector<float> visibility;           // the mean light of the pixel's rays: 0..1, its fraction of rays reaching the light through opaque casters
    std::vector<glm::vec3> coloured;         // the same per channel through translucent casters; empty with opaque ones
    std::vector<float> occluderDistance;     // m, from P to the first occluder, the mean over occluded rays; 0 where none is
    std::vector<uint32_t> occludedRays;      // how many of the pixel's rays met an occluder
    std::vector<float> lightAngle;           // radians: the angular diameter of the light's bounding sphere from P (0: a point light)
    uint64_t raysCast = 0;                   // rays traced (a pixel whose samples all face away from the light traces none)
};

// The buffers of frame `frame` of a sequence, `raysPerPixel` (>= 1) rays per pixel, traced
// by `rays` (the scene's, sceneRays); rows done reported to `progress` (null: nowhere).
// Throws std::invalid_argument for raysPerPixel < 1.
ShadowRayBuffers traceShadowRays(const ReferenceVisibility& rays, const GBuffer& gbuffer, const Light& light,
                                 int raysPerPixel, uint32_t frame, Progress* progress = nullptr);

// The angular diameter (radians) of `light`'s bounding sphere seen from P: 2 asin(r / d) for
// a disk or rectangle of bounding radius r at distance d (pi within it), a sun's angular
// diameter, 0 for a point or spot light and a point-like sun.
float lightAngularDiameter(const Light& light, const glm::vec3& P);

}  // namespace shadowlab
