// Reading triangle meshes from Wavefront OBJ files.
#pragma once

#include <string>

#include "scenes/scene.h"

namespace shadowlab {

// Positions ("v"), polygons ("f", triangulated as fans) of every object and group, and the
// normals ("vn") their corners name ("f 1//1 2//2 3//3"), as Mesh::cornerNormals with 0
// for a corner that names none; texture coordinates, lines, points and materials are
// ignored. Throws SceneError naming the file and the line or face for non-finite or
// unparsable coordinates or normals, indices out of range and faces with fewer than 3
// vertices.
Mesh readObj(const std::string& path);

// The same for a file's text already in memory; `path` names it in errors.
Mesh parseObj(const std::string& text, const std::string& path);

}  // namespace shadowlab
