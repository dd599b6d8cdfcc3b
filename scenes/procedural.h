// Procedural meshes for the built-in scenes. Front faces wind counter-clockwise seen from
// outside (from above, for the grid), as everywhere in shadowlab (conventions.md).
// Positions are computed in double and rounded once to float, so that symmetric points
// are exactly symmetric and sphere vertices lie within one float ulp of the radius.
// Each mesh carries its exact shading normals (Mesh::cornerNormals): +Y for the grid, the
// radial direction for the sphere, each face's normal for the box (which stays flat).
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "scenes/scene.h"

namespace shadowlab {

// A size.x by size.y rectangle in the xz plane at y = 0, centred on the origin, split
// into divisions.x by divisions.y squares of two triangles each; faces +Y.
// Requires size > 0 and divisions >= 1.
Mesh makeGrid(glm::vec2 size, glm::ivec2 divisions);

// A latitude-longitude sphere centred on the origin with one vertex at each pole, so the
// caps are triangle fans: slices * (stacks - 1) * 2 triangles, none degenerate.
// Requires radius > 0, slices >= 3, stacks >= 2.
Mesh makeUvSphere(float radius, int slices, int stacks);

// The triangles makeGrid and makeUvSphere make, known before making them (the loader
// checks a scene's limits from these).
inline uint64_t gridTriangleCount(glm::ivec2 divisions) { return 2 * uint64_t(divisions.x) * uint64_t(divisions.y); }
inline uint64_t uvSphereTriangleCount(int slices, int stacks) { return 2 * uint64_t(slices) * uint64_t(stacks - 1); }

// An axis-aligned box with 8 shared corners and 12 triangles. Requires min < max.
Mesh makeBox(glm::vec3 min, glm::vec3 max);

}  // namespace shadowlab
