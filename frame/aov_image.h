// A frame's buffers as the EXR `render --aov` writes (conventions.md, "Buffers written to
// disk"), for any caller that saves a frame as the command does (the Python module's
// Frame.write_exr).
#pragma once

#include "frame/render.h"
#include "shading/image_io.h"

namespace shadowlab {

// R G B (the shaded image), the G-buffer's channels (setGBuffer), each light's V
// (visibilityChannel(); a visibility technique's) and, in a frame of one light, the stencil
// if the technique has one.
ImageChannels aovImage(const Frame& frame);

}  // namespace shadowlab
