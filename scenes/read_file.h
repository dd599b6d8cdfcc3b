// Reading a whole file into memory, shared by the scene, OBJ and PLY readers.
#pragma once

#include <string>

namespace shadowlab {

// The file's bytes; throws SceneError naming the file and the reason if it cannot be read.
std::string readWholeFile(const std::string& path);

}  // namespace shadowlab
