#include "shadows/caster_transmission.h"

namespace shadowlab {

CasterTransmission::CasterTransmission(const Scene& scene, const WorldGeometry& world)
    : scene_(scene), world_(world), anyNonOpaque_(hasNonOpaqueCasters(scene)) {}

bool CasterTransmission::shareVertex(uint32_t a, uint32_t b) const {
    const glm::uvec3 s = world_.triangles[a], t = world_.triangles[b];
    for (int i = 0; i < 3; ++i) {
        if (s[i] == t.x || s[i] == t.y || s[i] == t.z) return true;
    }
    return false;
}

bool CasterTransmission::solidAt(uint32_t triangle, float u, float v) const {
    const Material& material = materialOf(triangle);
    const glm::vec2* uv = &world_.cornerUvs[3 * size_t(triangle)];
    const glm::vec2 at = (1.0f - u - v) * uv[0] + u * uv[1] + v * uv[2];
    const AlphaTexture& texture = scene_.alphaTextures[size_t(material.alphaTexture)];
    return texture.alpha[size_t(nearestTexelIndex(texture.width, texture.height, texture.wrap, at))] >= material.alphaCutoff;
}

glm::vec3 CasterTransmission::passedAt(uint32_t triangle, float u, float v) const {
    const Material& material = materialOf(triangle);
    if (material.cutOut() && !solidAt(triangle, u, v)) return glm::vec3(1.0f);
    return material.translucent() ? material.passed() : glm::vec3(0.0f);
}

}  // namespace shadowlab
