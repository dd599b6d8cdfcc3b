// Intermediate buffers a technique shows on request (`--debug-buffers DIR`): each is
// written as DIR/<technique>-<name>.exr (the exact float values, channel "Y") and
// DIR/<technique>-<name>.png (the values mapped linearly from [low, high] to black..white,
// for people); a radiance buffer as channels R, G, B and a tone-mapped PNG (the image's own
// tone mapping, shading/tonemap.h); a picture made for people (lights drawn on a map) as a
// PNG only. Row 0 is the top row, as for every image (conventions.md).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace shadowlab {

// RGB bytes for writePng(): `values` mapped linearly from [low, high] to black..white (a
// value outside clamped, a NaN or infinity black).
std::vector<uint8_t> greyImage(const std::vector<float>& values, float low, float high);

class DebugBuffers {
public:
    // An empty directory writes nothing; otherwise it is created if missing. A suffix ends
    // every name (<technique>-<name><suffix>): one map of several, a cube face's "-face-px".
    DebugBuffers(std::filesystem::path directory, std::string technique, std::string suffix = "");

    bool enabled() const { return !directory_.empty(); }
    void write(const std::string& name, int width, int height, const std::vector<float>& values, float low,
               float high) const;
    void writeRadiance(const std::string& name, int width, int height, const std::vector<glm::vec3>& radiance) const;
    void writePicture(const std::string& name, int width, int height, const std::vector<uint8_t>& rgb) const;

private:
    std::filesystem::path base(const std::string& name) const {
        return directory_ / (technique_ + "-" + name + suffix_);
    }

    std::filesystem::path directory_;
    std::string technique_, suffix_;
};

}  // namespace shadowlab
