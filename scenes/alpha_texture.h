// Reading the alpha texture of a cut-out material (foliage cards): the alpha channel of a
// PNG (or any image stb_image reads), as opacity in [0, 1] per texel, row 0 at the top.
#pragma once

#include <string>

#include <glm/glm.hpp>

#include "scenes/scene.h"

namespace shadowlab {

// Throws SceneError naming the file when it cannot be read, has no alpha channel (grey or
// RGB images have none), or is larger than 8192 texels on a side.
AlphaTexture readAlphaTexture(const std::string& path);

// The texel a texture coordinate falls in, nearest, the coordinates clamped to the texture
// (u right, v up, as in OBJ): the rule the rasterizer's alpha test (tile_raster.inl) and the
// reference's (shadows/caster_transmission.h) both follow, in float.
inline int alphaTexelIndex(const AlphaTexture& texture, glm::vec2 uv) {
    const float u = uv.x > 0.0f ? (uv.x < 1.0f ? uv.x : 1.0f) : 0.0f;
    const float v = uv.y > 0.0f ? (uv.y < 1.0f ? uv.y : 1.0f) : 0.0f;
    const int column = int(u * float(texture.width)), row = int((1.0f - v) * float(texture.height));
    return (row < texture.height ? row : texture.height - 1) * texture.width +
           (column < texture.width ? column : texture.width - 1);
}

}  // namespace shadowlab
