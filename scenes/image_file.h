// Reading the 8-bit images a scene or a compositing file names (cookies, cut-outs,
// photographs): one checked path for all of them. The format is told by the file's first
// bytes and must be one the reader accepts (docs/scene-format.md): PNG, and JPEG where the
// docs say so. Any other image (Radiance HDR, TGA, PNM, BMP, GIF, ...) is refused by name,
// for stb_image's decoders of those hang or return pixels they never wrote on a short file
// (Debian's stb_image 2.27). A PNG must end with its IEND chunk and a JPEG with its
// end-of-image marker, so that a truncated file is refused instead of decoded in part.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace shadowlab {

enum class ImageFormat { Png, Jpeg };

struct DecodedImage {
    int width = 0, height = 0;
    int fileChannels = 0;          // in the file: 1 grey, 2 grey + alpha, 3 RGB, 4 RGBA
    std::vector<uint8_t> bytes;    // `channels` per pixel as asked, row 0 at the top
};

// The image at `path` as `channels` (1 to 4) bytes per pixel. Throws SceneError naming the
// file for one it cannot read, a format not in `accepted`, a truncated file, or one over
// 8192 pixels on a side (checked before the pixels are decoded).
DecodedImage readImage(const std::string& path, int channels, std::initializer_list<ImageFormat> accepted);

// The same for an image already in memory (a glTF file's embedded or data-URI image);
// `path` names it in errors.
DecodedImage decodeImage(std::string_view bytes, const std::string& path, int channels,
                         std::initializer_list<ImageFormat> accepted);

}  // namespace shadowlab
