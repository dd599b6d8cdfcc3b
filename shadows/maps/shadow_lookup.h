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

#include "scenes/camera.h"
#include "scenes/scene.h"
#include "shading/gbuffer.h"
#include "shadows/depth_map.h"
#include "shadows/maps/pcf.h"
#include "shadows/maps/shadow_bias.h"

namespace shadowlab {

// The index of the map that serves the receiver at P (pixel k), or -1 for none (V = 0).
using MapSelector = std::function<int(const glm::dvec3& P, size_t pixel)>;

// The texel density is a diagnostic, not part of V: measured at every pixel for the debug
// view, and otherwise only at the pixels its median is taken over, every
// kDensitySampleStride-th pixel of every kDensitySampleStride-th row (a regular sample, the
// same whatever the thread count), so that it costs 1/16 of the lookup's time, not a third.
inline constexpr int kDensitySampleStride = 4;

struct ShadowLookup {
    int width = 0;
    std::vector<float> visibility;     // per pixel
    std::vector<float> texelDensity;   // map texels per screen pixel (area ratio), 0 where none or not measured
    std::vector<int8_t> mapIndex;      // the map used, -1 where none
};

// Unit direction from P to the light (a point-like light: pass pointLightFor()).
glm::dvec3 unitTowardsLight(const Light& light, const glm::dvec3& P);

// The area in map texels of the footprint of camera pixel (i, j) on the receiver plane
// (P, N): |det| of the Jacobian of the map's texel coordinates across one pixel step.
double texelsPerPixel(const DepthMap& map, const PixelRays& rays, int i, int j, const glm::dvec3& P, const glm::dvec3& N);

// everyPixelDensity: measure the texel density at every pixel (the debug view), not only
// at the sample its median is taken over.
ShadowLookup lookUpShadows(const GBuffer& receivers, const Camera& camera, const Light& light,
                           const std::vector<DepthMap>& maps, const MapSelector& select, const BiasSettings& bias,
                           const PcfKernel& kernel, bool everyPixelDensity = false);

// The median of the texel density over the sampled pixels a map served (0 if none).
double medianTexelDensity(const ShadowLookup& lookup);

}  // namespace shadowlab
