#include "shading/environment/environment_file.h"

#include <cmath>
#include <memory>
#include <stdexcept>

#include <stb_image.h>

#include "raster/fixed_point.h"
#include "scenes/read_file.h"
#include "shading/image_io.h"

namespace shadowlab {
namespace {

namespace fs = std::filesystem;

std::runtime_error fileError(const fs::path& path, const std::string& what) {
    return std::runtime_error("environment map " + path.string() + ": " + what);
}

// Radiance HDR through stb_image, which returns linear floats for RGBE files (and would
// apply a display gamma to an 8-bit file, so those are refused before decoding). Its
// failure reason is a process-wide string that another thread may overwrite, so the errors
// say what failed without it.
EnvironmentMap readRadianceHdr(const fs::path& path) {
    const std::string bytes = readWholeFile(path.string());
    const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
    const int length = int(std::min<size_t>(bytes.size(), size_t(INT32_MAX)));
    if (!stbi_is_hdr_from_memory(data, length)) throw fileError(path, "not a Radiance HDR file");
    int width = 0, height = 0, channels = 0;
    if (!stbi_info_from_memory(data, length, &width, &height, &channels)) {
        throw fileError(path, "stb_image cannot read its header");
    }
    if (width > raster::kMaxViewport || height > raster::kMaxViewport) {
        throw fileError(path, std::to_string(width) + " x " + std::to_string(height) + " texels, more than " +
                                  std::to_string(raster::kMaxViewport) + " on a side");
    }
    const std::unique_ptr<float, void (*)(void*)> rgb(stbi_loadf_from_memory(data, length, &width, &height, &channels, 3),
                                                      stbi_image_free);
    if (!rgb) throw fileError(path, "stb_image cannot decode it (truncated or corrupt)");
    EnvironmentMap map;
    map.width = width, map.height = height;
    map.radiance.resize(size_t(width) * size_t(height));
    for (size_t k = 0; k < map.radiance.size(); ++k) map.radiance[k] = {rgb.get()[3 * k], rgb.get()[3 * k + 1], rgb.get()[3 * k + 2]};
    return map;
}

EnvironmentMap readOpenExr(const fs::path& path) {
    const ImageChannels image = readExr(path, {channel::R, channel::G, channel::B});
    EnvironmentMap map;
    map.width = image.width, map.height = image.height;
    map.radiance.resize(image.pixelCount());
    const std::vector<float>&r = image.at(channel::R), &g = image.at(channel::G), &b = image.at(channel::B);
    for (size_t k = 0; k < map.radiance.size(); ++k) map.radiance[k] = {r[k], g[k], b[k]};
    return map;
}

// Refuses NaN and infinite texels (naming the first), clamps negative values to 0.
void clampToRadiance(EnvironmentMap& map, const fs::path& path) {
    for (size_t k = 0; k < map.radiance.size(); ++k) {
        glm::vec3& L = map.radiance[k];
        if (!std::isfinite(L.r) || !std::isfinite(L.g) || !std::isfinite(L.b)) {
            throw fileError(path, "texel (" + std::to_string(k % size_t(map.width)) + ", " +
                                      std::to_string(k / size_t(map.width)) + ") is not finite");
        }
        L = glm::max(L, glm::vec3(0.0f));
    }
}

}  // namespace

EnvironmentMap readEnvironmentMap(const fs::path& path, double rotationRadians) {
    const std::string extension = path.extension().string();
    EnvironmentMap map;
    if (extension == ".exr" || extension == ".EXR") {
        map = readOpenExr(path);
    } else if (extension == ".hdr" || extension == ".HDR" || extension == ".pic") {
        map = readRadianceHdr(path);
    } else {
        throw fileError(path, "unknown format '" + extension + "' (an environment map is .exr or .hdr)");
    }
    if (map.width < 2 || map.height < 1) {
        throw fileError(path, std::to_string(map.width) + " x " + std::to_string(map.height) + " texels, fewer than 2 x 1");
    }
    clampToRadiance(map, path);
    map.rotationRadians = rotationRadians;
    map.source = path.string();
    return map;
}

}  // namespace shadowlab
