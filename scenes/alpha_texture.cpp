#include "scenes/alpha_texture.h"

#include <memory>

#include <stb_image.h>

#include "scenes/scene_file.h"

namespace shadowlab {

AlphaTexture readAlphaTexture(const std::string& path) {
    const auto fail = [&](const std::string& problem) { throw SceneError(path + ": " + problem); };
    int width = 0, height = 0, channels = 0;
    if (stbi_info(path.c_str(), &width, &height, &channels) == 0) {
        fail(std::string("cannot read: ") + stbi_failure_reason());
    }
    if (width > 8192 || height > 8192) fail("larger than 8192 texels on a side");
    // stb_image counts 2 (grey, alpha) and 4 (RGBA) channels for images with alpha.
    if (channels != 2 && channels != 4) fail("has no alpha channel (a cut-out reads the image's alpha)");
    const std::unique_ptr<unsigned char, decltype(&stbi_image_free)> pixels(
        stbi_load(path.c_str(), &width, &height, &channels, 4), stbi_image_free);
    if (!pixels) fail(std::string("cannot read: ") + stbi_failure_reason());
    AlphaTexture texture{path, width, height, {}};
    texture.alpha.resize(size_t(width) * size_t(height));
    for (size_t k = 0; k < texture.alpha.size(); ++k) texture.alpha[k] = float(pixels.get()[4 * k + 3]) / 255.0f;
    return texture;
}

}  // namespace shadowlab
