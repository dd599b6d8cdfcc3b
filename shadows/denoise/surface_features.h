// The surface features the edge-stopping functions compare (Schied et al. 2017, SVGF,
// section 4.3): each pixel's depth, here its distance from the eye, and that depth's
// screen-space gradient, which scales the depth test to the surface's slope (eq. 3).
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "shading/gbuffer.h"
#include "shadows/denoise/denoise_inputs.h"

namespace shadowlab {

struct SurfaceFeatures {
    std::vector<float> depth;               // |P - eye|; 0 where hit = 0
    std::vector<glm::vec2> depthGradient;   // per pixel, central differences over hit neighbours (one-sided at a gap)
};

SurfaceFeatures surfaceFeatures(const GBuffer& gbuffer, const DenoiseView& view);

}  // namespace shadowlab
