// What a shadow denoiser reads (docs/denoisers.md): plain per-pixel buffers, as a ray tracer
// hands them over (docs/ray-traced-shadows.md) and as the denoisers' public descriptions
// list them (Schied et al. 2017, SVGF, section 4; AMD FidelityFX Shadow Denoiser's inputs:
// the shadow mask, depth, motion, normals; NVIDIA NRD's SIGMA: the hit distance and the
// tangent of the light's angular radius). Each denoiser is a chain of stages in this folder.
#pragma once

#include <span>

#include <glm/glm.hpp>

#include "shading/gbuffer.h"
#include "shadows/temporal/reprojection.h"

namespace shadowlab {

// The camera as the denoisers need it: where it is, and how many pixels one unit spans at
// unit distance (height / (2 tan(fovy / 2))), to turn a width on a surface into pixels.
struct DenoiseView {
    glm::vec3 eye{0.0f};
    float focalPixels = 1.0f;
};

// The light's size, for the penumbra estimate: a local light of `radius` at `position`, or
// a directional one (a sun) seen under an angular radius of atan(tanAngularRadius).
struct DenoiseLight {
    glm::vec3 position{0.0f};
    float radius = 0.0f;
    bool directional = false;
    float tanAngularRadius = 0.0f;
};

struct DenoiseInputs {
    const GBuffer& gbuffer;
    std::span<const float> visibility;         // this frame's noisy V per pixel, in [0, 1]
    // To the first occluder, over the pixel's blocked rays; 0 or +inf: no ray blocked (0 is
    // the ray-traced technique's sentinel: no occluder lies at 0, a ray starts above P).
    std::span<const float> occluderDistance;
    DenoiseView view;
    DenoiseLight light;
    const Reprojection* reprojection = nullptr;   // null: no frame before; every history starts afresh
};

// Throws std::invalid_argument unless V (and, if `needsDistance`, the occluder distance) has
// the G-buffer's size.
void checkDenoiseInputs(const DenoiseInputs& in, bool needsDistance);

}  // namespace shadowlab
