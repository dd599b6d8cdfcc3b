// The vertex stage: object space to clip space and, for every vertex that needs no
// clipping, on to snapped window coordinates, once per vertex rather than once per
// triangle that uses it. Structure-of-arrays loops: each lane the same IEEE operations in
// the same order, so the result does not depend on how the compiler vectorises them.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "raster/clip.h"
#include "raster/window.h"

namespace shadowlab::raster {

struct TransformedVertices {
    std::vector<float> x, y, z, w;            // clip space
    std::vector<uint8_t> clipCode;            // clipOutcode(), plus kNotProjectable
    std::vector<uint8_t> viewportCode;        // viewportOutcode()
    std::vector<WindowVertex> window;         // valid where clipCode == 0

    size_t size() const { return x.size(); }
    glm::vec4 clipPosition(uint32_t i) const { return {x[i], y[i], z[i], w[i]}; }
};

// Bit set in clipCode for a vertex that cannot be divided by w: w <= 0, or a coordinate
// that is not finite (an overflow to infinity in the transform, a NaN). Its triangles
// take the clipping path, which drops any polygon still holding such a vertex.
inline constexpr uint8_t kNotProjectable = 0x80;

struct Viewport {
    int width, height;
    ClipVolume volume;
};

// Positions with w = 1 (ordinary points).
void transformVertices(std::span<const glm::vec3> positions, const glm::mat4& clipFromObject,
                       const Viewport& viewport, TransformedVertices& out);
// Homogeneous positions (w = 0 for points at infinity, as shadow-volume extrusion needs).
void transformVertices(std::span<const glm::vec4> positions, const glm::mat4& clipFromObject,
                       const Viewport& viewport, TransformedVertices& out);

}  // namespace shadowlab::raster
