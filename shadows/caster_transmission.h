// How light passes the casters of a scene that are not opaque (conventions.md, "Casters that
// are not opaque"): per triangle what its material lets through, (1 - opacity) times its
// transmittance, the holes of cut-outs at a texture coordinate, and the density volumes.
// The exact reference multiplies these along its shadow rays; the volumetric techniques
// (shadows/deep/) draw the translucent triangles into the light's view with them.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "raster/nearest_texel.h"
#include "scenes/scene.h"

namespace shadowlab {

class CasterTransmission {
public:
    // The scene's materials, textures and volumes for the triangles of `world` (its
    // triangleMaterial and cornerUvs); both are read in place and must outlive this.
    CasterTransmission(const Scene& scene, const WorldGeometry& world);

    // Whether anything lets light through: otherwise every caster is opaque.
    bool anyNonOpaque() const { return anyNonOpaque_; }
    // The triangle's material; an opaque default where a scene made in code has none for it.
    const Material& materialOf(uint32_t triangle) const {
        const uint32_t m = world_.triangleMaterial[triangle];
        return m < scene_.materials.size() ? scene_.materials[m] : kOpaque;
    }
    uint32_t instanceOf(uint32_t triangle) const { return world_.triangleInstance[triangle]; }
    // Whether two triangles share a vertex (an edge or a corner of a mesh): a ray through
    // it hits both at one point of one surface.
    bool shareVertex(uint32_t a, uint32_t b) const;

    // The light triangle t passes, per channel, at barycentric coordinates (u, v) (the
    // point (1 - u - v) A + u B + v C): 0 where opaque, 1 in a cut-out's hole, the
    // material's passed() where translucent.
    glm::vec3 passedAt(uint32_t triangle, float u, float v) const;
    // Whether a cut-out triangle is solid at (u, v): its texture's alpha at the texel the
    // interpolated texture coordinate falls in (nearestTexelIndex) is at least the cutoff.
    bool solidAt(uint32_t triangle, float u, float v) const;

    std::span<const DensityVolume> volumes() const { return scene_.volumes; }

private:
    static inline const Material kOpaque{};
    const Scene& scene_;
    const WorldGeometry& world_;
    bool anyNonOpaque_;
};

}  // namespace shadowlab
