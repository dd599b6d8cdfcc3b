// The synthetic object as a frame uses it: the whole mesh for the camera (and the
// reference), and a copy simplified by meshoptimizer to a few hundred triangles for the
// shadow maps, which Gibson et al. 2003 render from "a simplified version of the object"
// (section 8, 100 to 500 triangles) since a frame draws one map per cluster.
#pragma once

#include <glm/glm.hpp>

#include "scenes/caster_lod.h"
#include "scenes/compositing_scene.h"

namespace shadowlab {

struct ObjectLevels {
    Scene whole;                  // one instance of the object's mesh, at the identity
    SimplifiedScene simplified;   // the same, simplified; its error in the mesh's units
};

// Throws std::invalid_argument for an object with no triangle or shadowTriangles < 4.
ObjectLevels objectLevels(const SyntheticObject& object, int shadowTriangles = 300);

// The level's triangles in world space at a placement (one frame of the object's path).
WorldGeometry placed(const Scene& level, const glm::mat4& placement);

// The largest factor by which a placement stretches a length.
double largestScale(const glm::mat4& placement);

}  // namespace shadowlab
