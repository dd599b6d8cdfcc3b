// The synthetic objects as a frame uses them: the whole meshes for the camera (and the
// reference), and copies simplified by meshoptimizer to a few hundred triangles each for
// the shadow maps, which Gibson et al. 2003 render from "a simplified version of the
// object" (section 7.2, 100 to 500 triangles) since a frame draws one map per cluster.
// Object i is instance, mesh and material i of both levels.
#pragma once

#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "differential/scene/compositing_scene.h"
#include "scenes/caster_lod.h"

namespace shadowlab {

struct ObjectLevels {
    Scene whole;                  // one instance per object, its albedo its material
    SimplifiedScene simplified;   // the same, simplified; its errors in the meshes' units
};

// Throws std::invalid_argument for no object, an object with no triangle or no frame, paths
// of different lengths, a placement that is not finite, or shadowTriangles < 4.
ObjectLevels objectLevels(std::span<const SyntheticObject> objects, int shadowTriangles = 300);

// Throws std::invalid_argument, naming `who`, unless every placement is finite.
void requireFinitePlacements(std::span<const glm::mat4> placements, const std::string& who);

// Each object's placement at frame k of the paths.
std::vector<glm::mat4> placementsAt(std::span<const SyntheticObject> objects, size_t frame);

// The level's triangles in world space, object i placed by placements[i]. Throws
// std::invalid_argument for a count that is not the level's.
WorldGeometry placed(const Scene& level, std::span<const glm::mat4> placements);

// The largest factor by which a placement stretches a length.
double largestScale(std::span<const glm::mat4> placements);

}  // namespace shadowlab
