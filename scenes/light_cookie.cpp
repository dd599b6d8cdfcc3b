#include "scenes/light_cookie.h"

#include <memory>

#include <stb_image.h>

#include "scenes/scene_file.h"

namespace shadowlab {

LightCookie readLightCookie(const std::string& path) {
    const auto fail = [&](const std::string& problem) { throw SceneError(path + ": " + problem); };
    int width = 0, height = 0, channels = 0;
    if (stbi_info(path.c_str(), &width, &height, &channels) == 0) {
        fail(std::string("cannot read: ") + stbi_failure_reason());
    }
    if (width > 8192 || height > 8192) fail("larger than 8192 texels on a side");
    const std::unique_ptr<unsigned char, decltype(&stbi_image_free)> pixels(
        stbi_load(path.c_str(), &width, &height, &channels, 3), stbi_image_free);
    if (!pixels) fail(std::string("cannot read: ") + stbi_failure_reason());
    LightCookie cookie{path, width, height, {}};
    cookie.texels.resize(size_t(width) * size_t(height));
    for (size_t k = 0; k < cookie.texels.size(); ++k) {
        const unsigned char* rgb = pixels.get() + 3 * k;
        cookie.texels[k] = glm::vec3(float(rgb[0]), float(rgb[1]), float(rgb[2])) / 255.0f;
    }
    return cookie;
}

}  // namespace shadowlab
