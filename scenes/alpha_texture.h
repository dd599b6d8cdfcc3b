// Reading the alpha texture of a cut-out material (foliage cards): the alpha channel of a
// PNG (or any image stb_image reads), as opacity in [0, 1] per texel, row 0 at the top.
#pragma once

#include <string>

#include "scenes/scene.h"

namespace shadowlab {

// Throws SceneError naming the file when it cannot be read, has no alpha channel (grey or
// RGB images have none), or is larger than 8192 texels on a side.
AlphaTexture readAlphaTexture(const std::string& path);

}  // namespace shadowlab
