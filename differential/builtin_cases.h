// The built-in cases `shadowlab composite` names (docs/differential-rendering.md): the room
// with the object slid under the desk or lifted off the floor (Figure 7), the forest
// panorama outdoors, and a real photograph of a chessboard. Their mesh, maps and photograph
// are read from the data folder.
#pragma once

#include <string>
#include <vector>

#include "differential/scene/compositing_scene.h"

namespace shadowlab {

struct BuiltinCompositingCase {
    CompositingScene scene;
    std::string note;   // what was fitted to the photograph, to be shown; empty if nothing
};

// The names, in the order the command's help gives them.
const std::vector<std::string>& builtinCompositingCaseNames();

// `width`, `height` apply to the room and outdoor cases; `dataDir` holds meshes/,
// environments/ and photos/. Throws std::invalid_argument for a name not in
// builtinCompositingCaseNames(), and what the readers and the cases throw.
BuiltinCompositingCase builtinCompositingCase(const std::string& name, int width, int height,
                                              const std::string& dataDir);

}  // namespace shadowlab
