#include "shading/surface_albedo.h"

#include <stdexcept>

#include "scenes/error_text.h"
#include "raster/nearest_texel.h"

namespace shadowlab {

glm::vec3 surfaceAlbedo(const Material& material, const std::vector<AlbedoTexture>& textures, const GBuffer& g,
                        size_t pixel) {
    if (!material.textured()) return material.albedo;
    if (g.uv.empty())
        throw std::invalid_argument("material " + inQuotes(material.name) +
                                    " has an albedo texture, but the G-buffer has no texture coordinates");
    const AlbedoTexture& texture = textures.at(size_t(material.albedoTexture));
    return material.albedo * texture.albedo[size_t(nearestTexelIndex(texture.width, texture.height, texture.wrap, g.uv[pixel]))];
}

}  // namespace shadowlab
