// What a compositing scene file names by path (differential/scene/compositing_file.h), read into the
// scene: the photograph (an EXR as linear radiance; a PNG or JPEG through the inverse of the
// file's camera response), cut to the camera's window, and an environment map put on a
// dome of distant sources (environment_dome.h).
#pragma once

#include "differential/scene/compositing_file.h"

namespace shadowlab {

// Throws std::runtime_error naming the file for one that cannot be read, and
// std::invalid_argument when the photograph is smaller than the camera's window or the dome
// is refused.
CompositingScene readCompositingInputs(const CompositingFile& file);

}  // namespace shadowlab
