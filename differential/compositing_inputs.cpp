#include "differential/compositing_inputs.h"

#include <filesystem>
#include <numbers>
#include <stdexcept>

#include "differential/environment_dome.h"
#include "shading/environment/environment_file.h"
#include "shading/image_io.h"
#include "shading/luminance.h"

namespace shadowlab {
namespace {

bool isExr(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
    return extension == ".exr";
}

// The photograph's linear radiance, and its size.
std::vector<glm::vec3> readPhotograph(const std::string& path, const CameraResponse& T, int& width, int& height) {
    std::vector<glm::vec3> radiance;
    if (isExr(path)) {
        const ImageChannels image = readExr(path, {"R", "G", "B"});
        width = image.width, height = image.height;
        const std::vector<float>&r = image.at("R"), &g = image.at("G"), &b = image.at("B");
        for (size_t k = 0; k < r.size(); ++k) radiance.push_back({r[k], g[k], b[k]});
        return radiance;
    }
    const Image8 image = readImage8(path);
    width = image.width, height = image.height;
    for (size_t k = 0; k < image.rgb.size(); k += 3) {
        radiance.push_back(glm::vec3(float(T.inverse(image.rgb[k])), float(T.inverse(image.rgb[k + 1])),
                                     float(T.inverse(image.rgb[k + 2]))));
    }
    return radiance;
}

}  // namespace

CompositingScene readCompositingInputs(const CompositingFile& file) {
    CompositingScene scene = file.scene;
    int width = 0, height = 0;
    const std::vector<glm::vec3> photograph = readPhotograph(file.photograph, scene.response, width, height);
    const Camera& camera = scene.camera;
    if (file.crop.x < 0 || file.crop.y < 0 || file.crop.x + camera.width > width ||
        file.crop.y + camera.height > height) {
        throw std::invalid_argument("compositing inputs: the photograph '" + file.photograph + "' (" +
                                    std::to_string(width) + " x " + std::to_string(height) +
                                    ") does not hold the camera's window");
    }
    for (int j = 0; j < camera.height; ++j) {
        for (int i = 0; i < camera.width; ++i) {
            scene.background.push_back(photograph[size_t(j + file.crop.y) * size_t(width) + size_t(i + file.crop.x)]);
        }
    }
    if (file.dome) {
        const DomeRequest& d = *file.dome;
        const EnvironmentMap map = readEnvironmentMap(d.map, d.rotationDeg * std::numbers::pi / 180.0);
        for (PatchSurface& sky : environmentDome(map, d.columns, d.rows, d.radiusM)) {
            if (d.grey) sky.emitted[0] = glm::dvec3(luminance(sky.emitted[0]));
            scene.surfaces.push_back(std::move(sky));
        }
    }
    return scene;
}

}  // namespace shadowlab
