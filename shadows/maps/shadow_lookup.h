// The second pass of shadow mapping (Real-Time Rendering, 4th ed., section 7.4, Figure
// 7.10): every camera pixel's surface point is taken into the light's map, compared (with
// the bias and filter chosen) and turned into V. One map serves each pixel: a single map,
// a cube face or a cascade, as a selector decides. Pixels are independent; rows run in
// parallel and no value is reduced across threads.
//
// As in the reference, V = 0 where the light is behind the surface, dot(N, L - P) <= 0,
// and outside a spot light's cone.
//
// The pass is compiled for its map selector and its filter (template arguments): the
// per-pixel work is straight-line code with no call through a pointer. It is still scalar
// double precision, as before, so its bits are unchanged (docs/peers.md: what remains).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/camera.h"
#include "scenes/scene.h"
#include "shading/gbuffer.h"
#include "shading/lights.h"
#include "shadows/depth_map.h"
#include "shadows/maps/pcf.h"
#include "shadows/maps/shadow_bias.h"
#include "shadows/receiver_pass.h"

namespace shadowlab {

// A map selector is a functor, select(P) = the index of the map that serves the receiver
// at P, or -1 for none (V = 0). The one for a single map:
struct OneMap {
    int operator()(const glm::dvec3&) const { return 0; }
};

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

// Unit directions from receivers to a point-like light (pass pointLightFor()); a
// directional light's is normalised once, not per pixel.
class TowardsLight {
public:
    explicit TowardsLight(const Light& light)
        : light_(light), direction_(glm::normalize(glm::dvec3(light.direction))) {}
    glm::dvec3 operator()(const glm::dvec3& P) const {
        return light_.type == LightType::Directional ? direction_ : glm::normalize(glm::dvec3(light_.position) - P);
    }

private:
    const Light& light_;
    glm::dvec3 direction_;
};

// The area in map texels of the footprint of camera pixel (i, j) on the receiver plane
// (P, N): |det| of the Jacobian of the map's texel coordinates across one pixel step.
double texelsPerPixel(const DepthMap& map, const PixelRays& rays, int i, int j, const glm::dvec3& P, const glm::dvec3& N);

inline bool inDensitySample(int i, int j) { return i % kDensitySampleStride == 0 && j % kDensitySampleStride == 0; }

// everyPixelDensity: measure the texel density at every pixel (the debug view), not only
// at the sample its median is taken over.
template <class MapSelector>
ShadowLookup lookUpShadows(const GBuffer& g, const Camera& camera, const Light& light, const std::vector<DepthMap>& maps,
                           const MapSelector& select, const BiasSettings& bias, const PcfKernel& kernel,
                           bool everyPixelDensity = false) {
    ShadowLookup out;
    out.width = g.width;
    out.visibility.assign(g.pixelCount(), 0.0f);
    out.texelDensity.assign(g.pixelCount(), 0.0f);
    out.mapIndex.assign(g.pixelCount(), -1);
    const PixelRays rays(camera);
    const TowardsLight towardsLight(light);
    withFilter(kernel, [&](const auto& filter) {
        // Every surface pixel, not only those the light reaches: the map serving a pixel and
        // its texel density are shown (and measured) wherever there is a surface.
        forEachSurfacePixel(g, [&](int i, int j, size_t k) {
            const glm::dvec3 P(g.position[k]), N(g.normal[k]);
            const int m = select(P);
            if (m < 0) return;
            out.mapIndex[k] = int8_t(m);
            if (everyPixelDensity || inDensitySample(i, j)) out.texelDensity[k] = float(texelsPerPixel(maps[m], rays, i, j, P, N));
            if (!lightReaches(light, g.position[k], g.normal[k])) return;
            const glm::dvec3 L = needsLightDirection(bias) ? towardsLight(P) : glm::dvec3(0.0);
            const MapReceiver r = mapReceiver(maps[m], P, N, L, bias);
            out.visibility[k] = float(filter(maps[m], r, k));
        });
    });
    return out;
}

// The median of the texel density over the sampled pixels a map served (0 if none).
double medianTexelDensity(const ShadowLookup& lookup);

}  // namespace shadowlab
