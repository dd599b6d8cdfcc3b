// Axis-aligned bounding boxes in world space, in double: what a light's or a shaft's
// conservative tests compare (a volume's reach of the near plane, an object's box against
// a shaft of line space).
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "scenes/scene.h"

namespace shadowlab {

struct Aabb {
    glm::dvec3 min, max;   // min <= max on every axis
};

// The box's centre.
inline glm::dvec3 centre(const Aabb& b) { return 0.5 * (b.min + b.max); }

// A ball, as a bound of a set of points.
struct Sphere {
    glm::dvec3 centre;
    double radius;
};

// The ball through the box's corners.
inline Sphere boundingSphere(const Aabb& b) { return {centre(b), 0.5 * glm::length(b.max - b.min)}; }

// The box holding both.
inline Aabb merged(const Aabb& a, const Aabb& b) { return {glm::min(a.min, b.min), glm::max(a.max, b.max)}; }

// Bounding box of every instance of the scene (WorldGeometry from flatten()), in instance order.
std::vector<Aabb> instanceBounds(const Scene& scene, const WorldGeometry& world);

}  // namespace shadowlab
