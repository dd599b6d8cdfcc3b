// Reading triangle meshes from PLY files (ASCII and binary little-endian).
#pragma once

#include <string>

#include "scenes/scene.h"

namespace shadowlab {

// Positions from the "vertex" element (x, y, z of any numeric type) and polygons from the
// "face" element's "vertex_indices" or "vertex_index" list, triangulated as fans
// (v0, v[i], v[i+1]); per-vertex normals (nx, ny, nz, all three or none) become
// Mesh::cornerNormals; every other element and property is skipped. Throws SceneError
// naming the file and the element row for malformed, truncated or inconsistent data:
// non-finite positions or normals, indices out of range, faces with fewer than 3 vertices.
Mesh readPly(const std::string& path);

// The same for a file's bytes already in memory; `path` names them in errors.
Mesh parsePly(const std::string& bytes, const std::string& path);

}  // namespace shadowlab
