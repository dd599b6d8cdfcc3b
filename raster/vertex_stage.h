// The vertex stage: object-space positions to clip space, structure-of-arrays, so the
// loop is a plain multiply-add over arrays that the compiler vectorises (each lane the
// same IEEE operations in the same order, so the result does not depend on the width).
#pragma once

#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace shadowlab::raster {

struct ClipVertices {
    std::vector<float> x, y, z, w;
    size_t size() const { return x.size(); }
};

// Positions with w = 1 (ordinary points).
void transformVertices(std::span<const glm::vec3> positions, const glm::mat4& clipFromObject, ClipVertices& out);
// Homogeneous positions (w = 0 for points at infinity, as shadow-volume extrusion needs).
void transformVertices(std::span<const glm::vec4> positions, const glm::mat4& clipFromObject, ClipVertices& out);

}  // namespace shadowlab::raster
