// Albedo textures (glTF's base colour texture, a scene file's "albedo-texture"): 8-bit sRGB
// texels decoded once, at load, to linear reflectance, for shading multiplies and adds
// radiometric quantities (glTF 2.0, section 3.9.2: "The base color texture MUST contain
// 8-bit values encoded with the sRGB opto-electronic transfer function").
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "scenes/scene.h"

namespace shadowlab {

// The sRGB electro-optical transfer function (IEC 61966-2-1; the inverse of the encoding
// in shading/tonemap.h) of an 8-bit value c, x = c / 255:
//     x / 12.92 for x <= 0.04045, else ((x + 0.055) / 1.055)^2.4,
// in double (portable::pow: the same bits on every CPU), rounded once to float.
float srgbToLinear(uint8_t c);

// `channels` bytes a texel (3 or 4, RGB first; alpha is not read), row 0 at the top, as
// linear albedo.
AlbedoTexture decodeAlbedoTexture(std::string source, int width, int height, std::span<const uint8_t> bytes,
                                  int channels);

// A PNG or JPEG file's colour (a grey image is grey albedo). Throws SceneError naming the
// file when it cannot be read or is larger than 8192 texels on a side.
AlbedoTexture readAlbedoTexture(const std::string& path);

}  // namespace shadowlab
