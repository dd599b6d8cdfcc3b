#include "shading/environment/environment_file.h"

#include <cmath>
#include <stdexcept>

#include "raster/fixed_point.h"
#include "scenes/read_file.h"
#include "shading/environment/radiance_hdr.h"
#include "shading/image_io.h"

namespace shadowlab {
namespace {

std::runtime_error fileError(const std::string& name, const std::string& what) {
    return std::runtime_error("environment map " + name + ": " + what);
}

EnvironmentMap fromExrChannels(const ImageChannels& image) {
    EnvironmentMap map;
    map.width = image.width, map.height = image.height;
    map.radiance.resize(image.pixelCount());
    const std::vector<float>&r = image.at(channel::R), &g = image.at(channel::G), &b = image.at(channel::B);
    for (size_t k = 0; k < map.radiance.size(); ++k) map.radiance[k] = {r[k], g[k], b[k]};
    return map;
}

// Refuses NaN and infinite texels (naming the first), clamps negative values to 0.
void clampToRadiance(EnvironmentMap& map, const std::string& name) {
    for (size_t k = 0; k < map.radiance.size(); ++k) {
        glm::vec3& L = map.radiance[k];
        if (!std::isfinite(L.r) || !std::isfinite(L.g) || !std::isfinite(L.b)) {
            throw fileError(name, "texel (" + std::to_string(k % size_t(map.width)) + ", " +
                                      std::to_string(k / size_t(map.width)) + ") is not finite");
        }
        L = glm::max(L, glm::vec3(0.0f));
    }
}

}  // namespace

EnvironmentMap parseEnvironmentMap(const std::string& bytes, const std::string& name, double rotationRadians) {
    // The format from the file's first bytes, not its name: EXR's magic number 76 2f 31 01,
    // Radiance's "#?".
    EnvironmentMap map;
    if (bytes.rfind(std::string("\x76\x2f\x31\x01", 4), 0) == 0) {
        map = fromExrChannels(parseExr(bytes, name));
    } else if (bytes.rfind("#?", 0) == 0) {
        map = parseRadianceHdr(bytes, name, raster::kMaxViewport);
    } else {
        throw fileError(name, "neither OpenEXR nor Radiance HDR (an 8-bit image holds display values, not radiance)");
    }
    if (map.width < 2 || map.height < 1) {
        throw fileError(name, std::to_string(map.width) + " x " + std::to_string(map.height) + " texels, fewer than 2 x 1");
    }
    clampToRadiance(map, name);
    map.rotationRadians = rotationRadians;
    map.source = name;
    return map;
}

EnvironmentMap readEnvironmentMap(const std::filesystem::path& path, double rotationRadians) {
    return parseEnvironmentMap(readWholeFile(path.string()), path.string(), rotationRadians);
}

}  // namespace shadowlab
