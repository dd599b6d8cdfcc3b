// Smooth shading normals. A triangle mesh approximates a curved surface; lighting it with
// each facet's plane normal shows the facets, and a glossy lobe (shading/environment/)
// turns every facet into its own mirror. Shading instead interpolates a normal per corner
// across each triangle (shading/gbuffer_build.h); these functions give every corner one.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "scenes/scene.h"

namespace shadowlab {

// One unit normal per vertex: the sum, over the triangles that use the vertex, of the
// triangle's unit normal times its angle at the vertex, normalised (Thürmer and Wüthrich,
// "Computing Vertex Normals from Polygonal Facets", JGT 3(1), 1998). Unlike area or
// uniform weights the result does not depend on how a face is split into triangles: a
// box corner gets (1, 1, 1)/sqrt(3) whichever way its quads are cut. Summed in double in
// triangle order. 0 for a vertex that only degenerate triangles use, or whose weighted
// normals cancel.
std::vector<glm::vec3> angleWeightedNormals(const Mesh& mesh);

// Three unit normals per triangle (corner c of triangle t at 3 t + c), object space: the
// mesh's own corner normal, normalised, where it gave a nonzero one; otherwise the
// angle-weighted vertex normal; otherwise the triangle's unit normal (0 for a degenerate
// triangle). Throws std::invalid_argument if mesh.cornerNormals is neither empty nor three
// per triangle, or holds a non-finite value (the file readers refuse those first).
std::vector<glm::vec3> cornerShadingNormals(const Mesh& mesh);

// What carries an instance's normals into world space: the cofactor matrix of the linear
// part M of worldFromObject, columns (b x c, c x a, a x b) for M's columns a, b, c. It is
// det(M) times the inverse transpose, so it keeps a normal perpendicular to the
// transformed surface under non-uniform scale, and it needs no division (the scene loader
// requires det(M) > 0, so the direction is kept too).
glm::dmat3 normalMatrix(const MeshInstance& instance);

// normalMatrix * n in double, normalised and rounded once to float; 0 stays 0.
glm::vec3 worldNormal(const glm::dmat3& normalMatrix, const glm::vec3& n);

}  // namespace shadowlab
