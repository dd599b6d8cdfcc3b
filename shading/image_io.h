// Image files: multi-channel float32 OpenEXR for checks, 8-bit sRGB PNG for people
// (conventions.md, "Buffers written to disk").
//
// Every file is written whole or not at all (scenes/write_file.h, writeFileAtomically;
// writeTextFile is there too). Errors are std::runtime_error naming the file.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "shading/gbuffer.h"

namespace shadowlab {

// Channel names, exactly as conventions.md lists them.
namespace channel {
inline constexpr const char* R = "R";
inline constexpr const char* G = "G";
inline constexpr const char* B = "B";
inline constexpr const char* Px = "P.x";
inline constexpr const char* Py = "P.y";
inline constexpr const char* Pz = "P.z";
inline constexpr const char* Nx = "N.x";
inline constexpr const char* Ny = "N.y";
inline constexpr const char* Nz = "N.z";
inline constexpr const char* Nsx = "Ns.x";   // the shading normal
inline constexpr const char* Nsy = "Ns.y";
inline constexpr const char* Nsz = "Ns.z";
inline constexpr const char* hit = "hit";
inline constexpr const char* V = "V";
inline constexpr const char* depth = "depth";
inline constexpr const char* motionX = "motion.x";   // GBuffer::motion's pixel offset, pixels
inline constexpr const char* motionY = "motion.y";
inline constexpr const char* stencil = "stencil";
inline constexpr const char* Y = "Y";   // one value: luminance of R, G, B, or a debug buffer
}  // namespace channel

// A set of named float channels of one size, row-major with row 0 at the top.
struct ImageChannels {
    int width = 0, height = 0;
    std::vector<std::string> names;
    std::vector<std::vector<float>> data;  // data[k] belongs to names[k]
    std::string source;                    // file it was read from, for error messages

    size_t pixelCount() const { return size_t(width) * size_t(height); }
    // The channel's values, or nullptr if there is no channel of that name.
    const std::vector<float>* find(std::string_view name) const;
    // The channel's values; throws std::runtime_error naming the channel and source.
    const std::vector<float>& at(std::string_view name) const;
    // Adds (or replaces) a channel; throws std::invalid_argument unless it has
    // width * height values.
    void set(std::string name, std::vector<float> values);
};

// Radiance as channels R, G, B.
void setRadiance(ImageChannels& image, const std::vector<glm::vec3>& radiance);
// The radiance of an image with channels R, G and B; nullopt if one is missing.
std::optional<std::vector<glm::vec3>> radianceOf(const ImageChannels& image);
// G-buffer as channels P.x P.y P.z N.x N.y N.z Ns.x Ns.y Ns.z hit depth, and motion.x motion.y
// in a frame with a frame before (GBuffer::motion). Sets the size from the G-buffer when the
// image is still empty.
void setGBuffer(ImageChannels& image, const GBuffer& gbuffer);

// One FLOAT channel per name, ZIP compression (lossless), scanlines top to bottom.
void writeExr(const std::filesystem::path& path, const ImageChannels& image);
// Every channel of the file, converted to float. Throws std::runtime_error naming the file
// for a file it cannot read, or one larger than the images shadowlab writes (more than
// 8192 pixels on a side or kMaxImageChannels, 32, channels), before allocating anything.
ImageChannels readExr(const std::filesystem::path& path);
// Only the named channels; throws std::runtime_error if one is missing.
ImageChannels readExr(const std::filesystem::path& path, const std::vector<std::string>& names);
// Every channel of an EXR file's bytes already in memory; `path` names them in errors.
ImageChannels parseExr(const std::string& bytes, const std::filesystem::path& path);

// 8-bit RGB, 3 bytes per pixel interleaved, row 0 at the top.
void writePng(const std::filesystem::path& path, int width, int height,
              const std::vector<uint8_t>& rgb);

// An 8-bit PNG or JPEG image (scenes/image_file.h, readImage), converted to RGB, row 0 at
// the top. Throws SceneError (a std::runtime_error) naming the file for one it cannot read,
// another format, a truncated file, or one over 8192 pixels on a side.
struct Image8 {
    int width = 0, height = 0;
    std::vector<uint8_t> rgb;   // 3 bytes per pixel
};
Image8 readImage8(const std::filesystem::path& path);

}  // namespace shadowlab
