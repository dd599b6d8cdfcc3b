#include "shadows/debug_buffers.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "shading/image_io.h"
#include "shading/tonemap.h"

namespace shadowlab {

std::vector<uint8_t> greyImage(const std::vector<float>& values, float low, float high) {
    std::vector<uint8_t> rgb(values.size() * 3);
    const float scale = high > low ? 1.0f / (high - low) : 0.0f;
    for (size_t k = 0; k < values.size(); ++k) {
        const float t = std::isfinite(values[k]) ? std::clamp((values[k] - low) * scale, 0.0f, 1.0f) : 0.0f;
        rgb[3 * k] = rgb[3 * k + 1] = rgb[3 * k + 2] = uint8_t(std::lround(t * 255.0f));
    }
    return rgb;
}

DebugBuffers::DebugBuffers(std::filesystem::path directory, std::string technique, std::string suffix)
    : directory_(std::move(directory)), technique_(std::move(technique)), suffix_(std::move(suffix)) {
    if (enabled()) std::filesystem::create_directories(directory_);
}

void DebugBuffers::write(const std::string& name, int width, int height, const std::vector<float>& values,
                         float low, float high) const {
    if (!enabled()) return;
    if (values.size() != size_t(width) * size_t(height)) throw std::logic_error("debug buffer " + name + ": wrong size");
    const std::filesystem::path base = this->base(name);
    ImageChannels exr;
    exr.width = width, exr.height = height;
    exr.set("Y", values);
    writeExr(base.string() + ".exr", exr);
    writePng(base.string() + ".png", width, height, greyImage(values, low, high));
}

void DebugBuffers::writeRadiance(const std::string& name, int width, int height,
                                 const std::vector<glm::vec3>& radiance) const {
    if (!enabled()) return;
    if (radiance.size() != size_t(width) * size_t(height)) throw std::logic_error("debug buffer " + name + ": wrong size");
    ImageChannels exr;
    exr.width = width, exr.height = height;
    setRadiance(exr, radiance);
    writeExr(base(name).string() + ".exr", exr);
    writePng(base(name).string() + ".png", width, height, toSrgb8Image(radiance, {}));
}

void DebugBuffers::writePicture(const std::string& name, int width, int height, const std::vector<uint8_t>& rgb) const {
    if (!enabled()) return;
    writePng(base(name).string() + ".png", width, height, rgb);
}

}  // namespace shadowlab
