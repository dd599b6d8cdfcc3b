// A compositing scene read from a JSON file (docs/scene-format.md, "Compositing scenes"), so
// that a user's own photograph, calibration and model can be composited: what
// differential/scene/compositing_scene.h holds, with the photograph, and any environment to be put on a
// dome as distant sources, named by their files (read by differential/
// compositing_inputs.h, which the scene library cannot reach).
#pragma once

#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "differential/scene/compositing_scene.h"

namespace shadowlab {

struct DomeRequest {
    std::string map;               // an environment map's path
    int columns = 32, rows = 8;
    double radiusM = 50.0;
    double rotationDeg = 0.0;
    bool grey = false;             // its luminance only (for a greyscale photograph)
};

struct CompositingFile {
    CompositingScene scene;        // its background still empty
    std::string photograph;        // the photograph's path (.exr: linear radiance; else 8-bit)
    glm::ivec2 crop{0};            // the window of the photograph the camera sees
    std::optional<DomeRequest> dome;
};

// Paths are relative to the file's folder. Throws SceneError naming the file and the field
// for anything malformed or out of range (compositing_scene.h's checks, and unknown keys).
CompositingFile loadCompositingFile(const std::string& path);
// The same for the file's text, read as if from `path` (the fuzz target's way in).
CompositingFile parseCompositingFile(const std::string& text, const std::string& path);

}  // namespace shadowlab
