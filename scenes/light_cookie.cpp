#include "scenes/light_cookie.h"

#include "scenes/image_file.h"

namespace shadowlab {

LightCookie readLightCookie(const std::string& path) {
    const DecodedImage image = readImage(path, 3, {ImageFormat::Png});
    LightCookie cookie{path, image.width, image.height, {}};
    cookie.texels.resize(size_t(image.width) * size_t(image.height));
    for (size_t k = 0; k < cookie.texels.size(); ++k) {
        const uint8_t* rgb = image.bytes.data() + 3 * k;
        cookie.texels[k] = glm::vec3(float(rgb[0]), float(rgb[1]), float(rgb[2])) / 255.0f;
    }
    return cookie;
}

}  // namespace shadowlab
