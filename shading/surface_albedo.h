// The surface's albedo at a pixel: its material's albedo times, for a textured material, the
// albedo texture's texel at the pixel's texture coordinate (glTF 2.0, section 3.9.2: base
// colour = factor * texture, both linear once the texture is decoded from sRGB). The texel
// is the nearest to (u, v) wrapped by the texture's sampler (raster/nearest_texel.h), the
// rule the cut-outs' alpha test follows; uv is the G-buffer's, perspective-correct (shading/gbuffer_build.h). Every
// stage that shades a G-buffer pixel reads its albedo here.
#pragma once

#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/scene.h"
#include "shading/gbuffer.h"

namespace shadowlab {

// `material` is the pixel's (the scene's, or a copy with other lobes: it keeps its
// albedoTexture index into `textures`). Throws std::invalid_argument for a textured
// material on a G-buffer without texture coordinates.
glm::vec3 surfaceAlbedo(const Material& material, const std::vector<AlbedoTexture>& textures, const GBuffer& g,
                        size_t pixel);

}  // namespace shadowlab
