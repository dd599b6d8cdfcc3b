// The texel a texture coordinate reads (raster/nearest_texel.inl, the one rule), for code
// outside the rasterizer's kernels: the rule compiled with the scalar SIMD types, the twin
// of the alpha test's vector lanes, so a texel is a hole to the references exactly where it
// is one to the camera pass and the depth maps.
#pragma once

#include <glm/glm.hpp>

#include "raster/simd/simd_scalar.h"
#include "raster/texture_wrap.h"

namespace shadowlab {

namespace nearest_texel_scalar {
namespace simd = shadowlab::simd_scalar;
#include "raster/nearest_texel.inl"
}  // namespace nearest_texel_scalar

inline int nearestTexelIndex(int width, int height, UvWrap wrap, glm::vec2 uv) {
    return nearest_texel_scalar::nearestTexelIndex(width, height, wrap, {uv.x}, {uv.y}).v;
}

}  // namespace shadowlab
