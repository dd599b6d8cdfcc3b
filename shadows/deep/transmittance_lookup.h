// The last stage of every volumetric shadow map: each camera pixel's receiver looked up in
// the light's maps. V is the opaque map's answer (the shadow-map lookup, shadow_lookup.h,
// with the shadow map's bias and filter) times the transmittance of the translucent casters
// and volumes in front of the receiver, which each technique stores per texel in its own
// way: `curve(texel, depth)` evaluates it. The receiver is moved `offsetTexels` texels along
// its normal (normal-offset bias: a strand must not shadow itself) and the four nearest
// texels' values are blended bilinearly (Lokovic and Veach 2000, section 4.1: a deep shadow
// map is filtered like a texture, not compared like a depth).
#pragma once

#include <cmath>
#include <vector>

#include <glm/glm.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "shading/gbuffer.h"
#include "shadows/depth_map.h"
#include "shadows/maps/shadow_lookup.h"

namespace shadowlab {

struct TransmittanceLookup {
    double offsetTexels = 1.5;    // along the normal, in texels at the receiver (`transmittance-offset`)
};

// Where receiver P (normal N, facing the camera) falls in the map: texel coordinates and
// window depth, after the normal offset.
inline glm::dvec3 offsetReceiver(const DepthMap& map, const glm::dvec3& P, const glm::dvec3& N, double offsetTexels) {
    const glm::dvec4 q = map.texelFromWorld * glm::dvec4(P, 1.0);
    const glm::dvec3 texel = glm::dvec3(q) / q.w;
    const glm::dvec4 side = map.worldFromTexel * glm::dvec4(texel.x + 1.0, texel.y, texel.z, 1.0);
    const double texelMetres = glm::length(glm::dvec3(side) / side.w - P);
    const glm::dvec4 moved = map.texelFromWorld * glm::dvec4(P + offsetTexels * texelMetres * N, 1.0);
    return glm::dvec3(moved) / moved.w;
}

// The value at texel coordinates (x, y) and depth z, bilinear over the four nearest texel
// centres (clamped to the map).
template <class Curve>
auto bilinearTransmittance(const Curve& curve, int size, const glm::dvec3& at) {
    const double x = at.x - 0.5, y = at.y - 0.5;
    const int x0 = texelIndexOf(x), y0 = texelIndexOf(y);
    const float fx = float(x - x0), fy = float(y - y0);
    const auto value = [&](int i, int j) {
        i = std::clamp(i, 0, size - 1), j = std::clamp(j, 0, size - 1);
        return curve(size_t(j) * size_t(size) + size_t(i), float(at.z));
    };
    return (1.0f - fy) * ((1.0f - fx) * value(x0, y0) + fx * value(x0 + 1, y0)) +
           fy * ((1.0f - fx) * value(x0, y0 + 1) + fx * value(x0 + 1, y0 + 1));
}

// The transmittance at every pixel's receiver (Value: float, or glm::vec3 per channel), 0
// where the opaque lookup says the light does not reach (opaqueV = 0 skips the curve).
template <class Curve>
auto lookUpTransmittance(const GBuffer& g, const DepthMap& map, const std::vector<float>& opaqueV,
                         const TransmittanceLookup& settings, const Curve& curve) {
    using Value = decltype(curve(size_t(0), 0.0f));
    std::vector<Value> out(g.pixelCount(), Value(0.0f));
    tbb::parallel_for(tbb::blocked_range<int>(0, g.height), [&](const tbb::blocked_range<int>& rows) {
        for (int j = rows.begin(); j < rows.end(); ++j) {
            for (int i = 0; i < g.width; ++i) {
                const size_t k = g.index(i, j);
                if (opaqueV[k] == 0.0f) continue;
                const glm::dvec3 at =
                    offsetReceiver(map, glm::dvec3(g.position[k]), glm::dvec3(g.normal[k]), settings.offsetTexels);
                out[k] = opaqueV[k] * bilinearTransmittance(curve, map.size, at);
            }
        }
    });
    return out;
}

}  // namespace shadowlab
