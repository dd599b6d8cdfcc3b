// Writing world-space geometry as a Wavefront OBJ file, for inspection in other tools
// ("shadowlab export-obj SCENE OUT.obj").
#pragma once

#include <string>

#include "scenes/scene.h"

namespace shadowlab {

// One "v" line per world position, printed with %.9g so that reading it back as float
// gives the same bits, and one 1-based "f" line per triangle. The file is written under
// a temporary name in the same directory and renamed, so it is either whole or absent.
// Throws std::runtime_error naming the file if it cannot be written.
void writeObj(const WorldGeometry& geometry, const std::string& path);

}  // namespace shadowlab
