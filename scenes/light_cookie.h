// Reading a spot light's cookie (gobo map, scene.h, LightCookie) from an image file: a
// grey or RGB PNG (or any image stb_image reads), 8 bits per channel, each texel's value /
// 255 the fraction of the light it lets through, as a mask, not sRGB-decoded; grey is
// copied to the three channels and an alpha channel is ignored.
#pragma once

#include <string>

#include "scenes/scene.h"

namespace shadowlab {

// Throws SceneError naming the file when it cannot be read or is larger than 8192 texels
// on a side.
LightCookie readLightCookie(const std::string& path);

}  // namespace shadowlab
