// The texel a texture coordinate falls in: nearest, the coordinates clamped to the texture
// (u right, v up, as in OBJ; row 0 at the top). The one rule every texture here is read
// by: the rasterizer's alpha test (tile_raster.inl), the reference's (shadows/
// caster_transmission.h) and the surface's albedo (shading/surface_albedo.h), in float.
#pragma once

#include <glm/glm.hpp>

namespace shadowlab {

inline int nearestTexelIndex(int width, int height, glm::vec2 uv) {
    const float u = uv.x > 0.0f ? (uv.x < 1.0f ? uv.x : 1.0f) : 0.0f;
    const float v = uv.y > 0.0f ? (uv.y < 1.0f ? uv.y : 1.0f) : 0.0f;
    const int column = int(u * float(width)), row = int((1.0f - v) * float(height));
    return (row < height ? row : height - 1) * width + (column < width ? column : width - 1);
}

}  // namespace shadowlab
