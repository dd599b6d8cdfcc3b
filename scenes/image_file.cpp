#include "scenes/image_file.h"

#include <algorithm>
#include <limits>
#include <memory>
#include <string_view>

#include <stb_image.h>

#include "scenes/read_file.h"
#include "scenes/scene_error.h"

namespace shadowlab {
namespace {

constexpr int kMaxSide = 8192;

bool startsWith(std::string_view bytes, std::string_view magic) { return bytes.substr(0, magic.size()) == magic; }

// The format the first bytes name; "" for PNG and JPEG, which the caller then checks.
std::string otherFormatOf(std::string_view b) {
    if (startsWith(b, "#?RADIANCE") || startsWith(b, "#?RGBE")) return "a Radiance HDR image";
    if (startsWith(b, "v/1\x01")) return "an OpenEXR image";
    if (startsWith(b, "GIF8")) return "a GIF image";
    if (startsWith(b, "BM")) return "a BMP image";
    if (startsWith(b, "8BPS")) return "a Photoshop image";
    if (startsWith(b, "\x53\x80\xf6\x34")) return "a Softimage PIC image";
    if (b.size() >= 2 && b[0] == 'P' && b[1] >= '1' && b[1] <= '7') return "a PNM image";
    return "not an image this program reads (TGA, say, which has no signature)";
}

const char* nameOf(ImageFormat format) { return format == ImageFormat::Png ? "PNG" : "JPEG"; }

ImageFormat formatOf(std::string_view bytes, const std::string& path, std::initializer_list<ImageFormat> accepted) {
    const auto fail = [&](const std::string& problem) { throw SceneError(path + ": " + problem); };
    std::string names;
    for (const ImageFormat f : accepted) names += std::string(names.empty() ? "" : " or ") + nameOf(f);
    ImageFormat format = ImageFormat::Png;
    if (startsWith(bytes, "\x89PNG\r\n\x1a\n")) format = ImageFormat::Png;
    else if (startsWith(bytes, "\xff\xd8\xff")) format = ImageFormat::Jpeg;
    else fail("is " + otherFormatOf(bytes) + "; here only " + names + " is read");
    if (std::ranges::find(accepted, format) == accepted.end())
        fail(std::string("is a ") + nameOf(format) + " image; here only " + names + " is read");
    // The last chunk of a PNG (length 0, "IEND", its CRC); a JPEG's end-of-image marker.
    constexpr std::string_view kPngEnd("\0\0\0\0IEND\xae\x42\x60\x82", 12), kJpegEnd("\xff\xd9");
    const std::string_view end = format == ImageFormat::Png ? kPngEnd : kJpegEnd;
    if (!bytes.ends_with(end))
        fail(std::string("is truncated: a ") + nameOf(format) + " file ends with its " +
             (format == ImageFormat::Png ? "IEND chunk" : "end-of-image marker (FF D9)"));
    return format;
}

}  // namespace

DecodedImage readImage(const std::string& path, int channels, std::initializer_list<ImageFormat> accepted) {
    return decodeImage(readWholeFile(path), path, channels, accepted);
}

DecodedImage decodeImage(std::string_view bytes, const std::string& path, int channels,
                         std::initializer_list<ImageFormat> accepted) {
    const auto fail = [&](const std::string& problem) { throw SceneError(path + ": " + problem); };
    formatOf(bytes, path, accepted);
    const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
    if (bytes.size() > size_t(std::numeric_limits<int>::max())) fail("more bytes than an image may have (2^31 - 1)");
    const int size = int(bytes.size());
    DecodedImage image;
    if (stbi_info_from_memory(data, size, &image.width, &image.height, &image.fileChannels) == 0)
        fail(std::string("cannot read: ") + stbi_failure_reason());
    if (image.width > kMaxSide || image.height > kMaxSide) fail("larger than 8192 pixels on a side");
    int ignored = 0;
    const std::unique_ptr<stbi_uc, decltype(&stbi_image_free)> pixels(
        stbi_load_from_memory(data, size, &image.width, &image.height, &ignored, channels), stbi_image_free);
    if (!pixels) fail(std::string("cannot read: ") + stbi_failure_reason());
    image.bytes.assign(pixels.get(), pixels.get() + size_t(image.width) * size_t(image.height) * size_t(channels));
    return image;
}

}  // namespace shadowlab
