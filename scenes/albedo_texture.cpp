#include "scenes/albedo_texture.h"

#include <array>
#include <stdexcept>

#include "raster/portable_math.h"
#include "scenes/image_file.h"

namespace shadowlab {

float srgbToLinear(uint8_t c) {
    const double x = double(c) / 255.0;
    return float(x <= 0.04045 ? x / 12.92 : portable::pow((x + 0.055) / 1.055, 2.4));
}

AlbedoTexture decodeAlbedoTexture(std::string source, int width, int height, std::span<const uint8_t> bytes,
                                  int channels) {
    const size_t texels = size_t(width) * size_t(height);
    if ((channels != 3 && channels != 4) || bytes.size() != texels * size_t(channels))
        throw std::invalid_argument("decodeAlbedoTexture: " + source + " has not 3 or 4 bytes per texel");
    // 256 values, so each is computed once however large the texture.
    std::array<float, 256> linear;
    for (int c = 0; c < 256; ++c) linear[size_t(c)] = srgbToLinear(uint8_t(c));
    AlbedoTexture texture{std::move(source), width, height, {}, {}};
    texture.albedo.resize(texels);
    for (size_t k = 0; k < texels; ++k) {
        const uint8_t* t = &bytes[size_t(channels) * k];
        texture.albedo[k] = {linear[t[0]], linear[t[1]], linear[t[2]]};
    }
    return texture;
}

AlbedoTexture readAlbedoTexture(const std::string& path) {
    const DecodedImage image = readImage(path, 3, {ImageFormat::Png, ImageFormat::Jpeg});
    return decodeAlbedoTexture(path, image.width, image.height, image.bytes, 3);
}

}  // namespace shadowlab
