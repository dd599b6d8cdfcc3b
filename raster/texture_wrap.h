// How a texture coordinate outside [0, 1] reads its texture, per axis: glTF 2.0's sampler
// modes (section 3.8.4, wrapS and wrapT), as OpenGL 4.6 section 8.14.2 defines them. The
// rule, in float and the same on every SIMD level, is raster/nearest_texel.inl.
#pragma once

#include <cstdint>

namespace shadowlab {

enum class TextureWrap : uint8_t { ClampToEdge, Repeat, MirroredRepeat };

// A texture's wrap along u (glTF's wrapS) and along v (wrapT). Scene files' textures clamp.
struct UvWrap {
    TextureWrap u = TextureWrap::ClampToEdge;
    TextureWrap v = TextureWrap::ClampToEdge;
};

}  // namespace shadowlab
