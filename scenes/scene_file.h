// Loading scenes from JSON files (docs/scene-format.md) and naming the built-in ones.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "scenes/scene.h"

namespace shadowlab {

// Any problem with a scene or mesh file. The message always starts with the file and,
// inside a JSON file, the path of the offending field, so that it can be fixed without
// a debugger: "scenes/x.json: lights[0].radius: must be > 0, got -1".
class SceneError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// nameOrPath is a path when it ends in ".json" or contains a '/', otherwise the stem of a
// built-in scene file. Throws SceneError for every invalid or unreadable input.
Scene loadScene(const std::string& nameOrPath);

// Stems of the *.json files in the built-in scene directory, sorted.
std::vector<std::string> builtinSceneNames();

// The built-in scene directory: $SHADOWLAB_SCENE_DIR if set, else the source tree's scenes/.
std::string builtinSceneDir();

}  // namespace shadowlab
