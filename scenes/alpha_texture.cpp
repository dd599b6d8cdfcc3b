#include "scenes/alpha_texture.h"

#include "scenes/image_file.h"
#include "scenes/scene_error.h"

namespace shadowlab {

AlphaTexture readAlphaTexture(const std::string& path) {
    const DecodedImage image = readImage(path, 4, {ImageFormat::Png});
    // Grey + alpha or RGBA: a cut-out reads the image's alpha.
    if (image.fileChannels != 2 && image.fileChannels != 4)
        throw SceneError(path + ": has no alpha channel (a cut-out reads the image's alpha)");
    AlphaTexture texture{path, image.width, image.height, {}, {}};
    texture.alpha.resize(size_t(image.width) * size_t(image.height));
    for (size_t k = 0; k < texture.alpha.size(); ++k) texture.alpha[k] = float(image.bytes[4 * k + 3]) / 255.0f;
    return texture;
}

}  // namespace shadowlab
