// The second pass of shadow mapping (Real-Time Rendering, 4th ed., section 7.4, Figure
// 7.10): every camera pixel's surface point is taken into the light's map, compared (with
// the bias and filter chosen) and turned into V. One map serves each pixel: a single map,
// a cube face or a cascade, as a selector decides. Pixels are independent; rows run in
// parallel and no value is reduced across threads.
//
// As in the reference, V = 0 where the light is behind the surface, dot(N, L - P) <= 0,
// and outside a spot light's cone.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/scene.h"
#include "shading/gbuffer.h"
#include "shadows/depth_map.h"
#include "shadows/pcf.h"
#include "shadows/shadow_bias.h"

namespace shadowlab {

// The index of the map that serves the receiver at P (pixel k), or -1 for none (V = 0).
using MapSelector = std::function<int(const glm::dvec3& P, size_t pixel)>;

struct ShadowLookup {
    std::vector<float> visibility;     // per pixel
    std::vector<float> texelDensity;   // map texels per screen pixel (area ratio), 0 where none
    std::vector<int8_t> mapIndex;      // the map used, -1 where none
};

// Unit direction from P to the light (a point-like light: pass pointLightFor()).
glm::dvec3 unitTowardsLight(const Light& light, const glm::dvec3& P);

// The area in map texels of the footprint of camera pixel (i, j) on the receiver plane
// (P, N): |det| of the Jacobian of the map's texel coordinates across one pixel step.
// worldFromClip is the inverse of the camera's clipFromWorldD.
double texelsPerPixel(const DepthMap& map, const Camera& camera, const glm::dmat4& worldFromClip, int i, int j,
                      const glm::dvec3& P, const glm::dvec3& N);

ShadowLookup lookUpShadows(const GBuffer& receivers, const Camera& camera, const Light& light,
                           const std::vector<DepthMap>& maps, const MapSelector& select, const BiasSettings& bias,
                           const PcfKernel& kernel);

// The median of the texel density over the pixels a map served (0 if none).
double medianTexelDensity(const ShadowLookup& lookup);

}  // namespace shadowlab
