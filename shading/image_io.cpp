// Image files. OpenEXR's scanline files have row 0 of the data window at the top, which
// matches our pixel convention, so buffers are passed through without flipping; the same
// holds for PNG. Writes go through writeFileAtomically() (see image_io.h for why).
#include "shading/image_io.h"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string_view>
#include <utility>

#include <unistd.h>

#include <Iex.h>
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStdIO.h>
#include <stb_image_write.h>

#include "raster/fixed_point.h"
#include "scenes/error_text.h"
#include "scenes/image_file.h"
#include "scenes/read_file.h"
#include "scenes/scene_error.h"
#include "scenes/scene_limits.h"
#include "scenes/write_file.h"

namespace shadowlab {
namespace fs = std::filesystem;

namespace {

std::string quotedPath(const fs::path& path) { return "'" + oneLine(path.string()) + "'"; }

// A name no other writer uses: the same directory (so rename() stays within one file
// system), hidden, and unique per process and per call.
void checkWritable(const ImageChannels& image) {
    if (image.width <= 0 || image.height <= 0 || image.names.empty()) {
        throw std::invalid_argument("image is empty");
    }
    if (image.names.size() != image.data.size()) {
        throw std::invalid_argument("image has " + std::to_string(image.names.size()) + " names for " +
                                    std::to_string(image.data.size()) + " channels");
    }
    for (size_t k = 0; k < image.names.size(); ++k) {
        if (image.data[k].size() != image.pixelCount()) {
            throw std::invalid_argument("channel '" + image.names[k] + "' has " +
                                        std::to_string(image.data[k].size()) + " values for " +
                                        std::to_string(image.pixelCount()) + " pixels");
        }
    }
}

void writeExrFile(const fs::path& file, const ImageChannels& image) {
    Imf::Header header(image.width, image.height);
    header.compression() = Imf::ZIP_COMPRESSION;  // lossless: checks need the exact floats
    Imf::FrameBuffer frameBuffer;
    for (size_t k = 0; k < image.names.size(); ++k) {
        header.channels().insert(image.names[k], Imf::Channel(Imf::FLOAT));
        frameBuffer.insert(image.names[k],
                           Imf::Slice::Make(Imf::FLOAT, image.data[k].data(), Imath::V2i(0, 0),
                                            image.width, image.height));
    }
    Imf::OutputFile output(file.c_str(), header);
    output.setFrameBuffer(frameBuffer);
    output.writePixels(image.height);
}

std::vector<std::string> channelNamesOf(const Imf::Header& header) {
    std::vector<std::string> names;
    for (auto it = header.channels().begin(); it != header.channels().end(); ++it) {
        names.emplace_back(it.name());
    }
    return names;
}

// The buffers are sized from the header, so the header is checked first: no larger than the
// images shadowlab writes (raster::kMaxViewport on a side, kMaxImageChannels channels).
void checkExrSize(const fs::path& path, int64_t width, int64_t height, size_t channels) {
    if (width < 1 || height < 1 || width > raster::kMaxViewport || height > raster::kMaxViewport) {
        throw std::runtime_error("EXR file " + quotedPath(path) + ": its data window is " + std::to_string(width) + " x " +
                                 std::to_string(height) + " pixels; images must be 1.." +
                                 std::to_string(raster::kMaxViewport) + " on a side");
    }
    if (channels > kMaxImageChannels) {
        throw std::runtime_error("EXR file " + quotedPath(path) + ": " + std::to_string(channels) +
                                 " channels, more than " + std::to_string(kMaxImageChannels));
    }
}

// OpenEXR 3.1 allocates what a header declares before it learns whether the file holds it:
// a value of any declared size for an attribute of unknown type, a string of any length in
// a stringvector, a preview image of any width and height, line-offset tables for the data
// window; and it reads a value of a known type by the type's own layout, whatever size the
// header declares, so a header can say one thing to a checker and another to the library.
// (Found by tests/fuzz: files of 400 bytes that asked for 2 GB.) So the headers are walked
// here first, value by value as the library reads them, in the layout of "OpenEXR File
// Layout": the magic number, a version word (bit 12: multi-part), then per part the
// attributes as "name\0type\0", an int32 size and the value, ended by an empty name; a
// multi-part file ends its list of headers with an empty one. Every value must take exactly
// the bytes it declares, within the file, and every data window must pass checkExrSize().
[[noreturn]] void refuseExrHeader(const fs::path& path, const std::string& why) {
    throw std::runtime_error("EXR file " + quotedPath(path) + ": " + why);
}

// Tiles: more than any writer uses (32 to 256 are usual), and small enough that a tile of
// 32 float channels stays within 512 MB, two channels of the largest image.
constexpr int64_t kMaxExrTileSide = 2048;

// Names are at most 31 bytes, or 255 in a file with the long-names flag (version bit 10);
// the library stops reading a name at that length, so a longer one would desynchronise it.
std::string readExrName(Imf::IStream& stream, size_t maxLength, const fs::path& path) {
    std::string name;
    for (char c = 0; stream.read(&c, 1), c != '\0';) {
        if (name.size() == maxLength)
            refuseExrHeader(path, "a header name longer than " + std::to_string(maxLength) + " bytes" +
                                      (maxLength < 255 ? " (the file does not set the long-names flag)" : ""));
        name += c;
    }
    return name;
}

int32_t readExrInt32(Imf::IStream& stream) {
    char bytes[4];
    stream.read(bytes, 4);
    int32_t value;
    std::memcpy(&value, bytes, 4);   // little-endian, as the file format and x86-64 are
    return value;
}

// The bytes of a value of a fixed-size type, or -1 for a type of variable size.
int64_t fixedExrValueBytes(std::string_view type) {
    static constexpr std::pair<std::string_view, int64_t> kFixed[] = {
        {"box2i", 16}, {"box2f", 16},   {"chromaticities", 32}, {"compression", 1}, {"double", 8}, {"envmap", 1},
        {"float", 4},  {"int", 4},      {"keycode", 28},        {"lineOrder", 1},   {"m33f", 36},  {"m33d", 72},
        {"m44f", 64},  {"m44d", 128},   {"rational", 8},        {"tiledesc", 9},    {"timecode", 8}, {"v2i", 8},
        {"v2f", 8},    {"v2d", 16},     {"v3i", 12},            {"v3f", 12},        {"v3d", 24},
        {"deepImageState", 1}};
    for (const auto& [name, bytes] : kFixed)
        if (name == type) return bytes;
    return -1;
}

// Reads one attribute's value of `size` bytes (already known to lie within the file) as
// OpenEXR will, and leaves the stream after it.
void checkExrValue(Imf::IStream& stream, const std::string& name, const std::string& type, int64_t size,
                   size_t maxNameLength, const fs::path& path) {
    const uint64_t start = stream.tellg();
    const auto mismatch = [&](const std::string& holds) {
        refuseExrHeader(path, "header attribute '" + name + "' of type '" + type + "' declares " +
                                  std::to_string(size) + " bytes but holds " + holds);
    };
    const auto consumed = [&] { return int64_t(stream.tellg() - start); };
    if (const int64_t fixed = fixedExrValueBytes(type); fixed >= 0) {
        if (size != fixed) mismatch(std::to_string(fixed));
        if (name == "dataWindow" && type == "box2i") {
            const int64_t xMin = readExrInt32(stream), yMin = readExrInt32(stream);
            const int64_t xMax = readExrInt32(stream), yMax = readExrInt32(stream);
            checkExrSize(path, xMax - xMin + 1, yMax - yMin + 1, 0);
        } else if (type == "tiledesc") {   // the library allocates a tile's pixels per thread
            const int64_t tileWidth = uint32_t(readExrInt32(stream)), tileHeight = uint32_t(readExrInt32(stream));
            if (tileWidth < 1 || tileHeight < 1 || tileWidth > kMaxExrTileSide || tileHeight > kMaxExrTileSide) {
                refuseExrHeader(path, "tiles of " + std::to_string(tileWidth) + " x " +
                                          std::to_string(tileHeight) + " pixels; tiles must be 1.." +
                                          std::to_string(kMaxExrTileSide) + " on a side");
            }
        }
    } else if (type == "chlist") {   // channels until an empty name, 16 bytes after each name
        while (consumed() <= size && !readExrName(stream, maxNameLength, path).empty()) {
            stream.seekg(stream.tellg() + 16);
        }
        if (consumed() != size) mismatch(std::to_string(consumed()) + (consumed() > size ? " or more" : ""));
    } else if (type == "stringvector") {   // int32 length + bytes, until the size is used up
        while (consumed() < size) {
            const int64_t length = readExrInt32(stream);
            if (length < 0 || length > size - consumed()) mismatch("a string of " + std::to_string(length) + " bytes");
            stream.seekg(stream.tellg() + uint64_t(length));
        }
        if (consumed() != size) mismatch(std::to_string(consumed()));
    } else if (type == "preview") {   // width, height, then 4 bytes per pixel
        if (size < 8) mismatch("a width and a height (8 bytes)");
        const uint64_t width = uint32_t(readExrInt32(stream)), height = uint32_t(readExrInt32(stream));
        // 4 w h is compared only where it cannot wrap: w h <= (size - 8) / 4 < 2^29.
        const bool small = width == 0 || height <= (uint64_t(size) - 8) / 4 / width;
        if (!small || 8 + 4 * width * height != uint64_t(size))
            mismatch("a " + std::to_string(width) + " x " + std::to_string(height) + " preview");
    } else if (type == "floatvector" && size % 4 != 0) {   // the library reads size / 4 floats
        mismatch("whole floats only (a multiple of 4 bytes)");
    } else if (type == "idmanifest") {   // OpenEXR 3.1 reads 4 bytes more than the size says
        refuseExrHeader(path, "header attribute '" + name + "' is an ID manifest, which shadowlab does not read");
    }
    stream.seekg(start + uint64_t(size));
}

void checkExrHeaders(Imf::IStream& stream, uint64_t fileBytes, const fs::path& path) {
    if (readExrInt32(stream) != 20000630) refuseExrHeader(path, "not an EXR file (no magic number)");
    const int32_t version = readExrInt32(stream);
    const bool multiPart = (version & 0x1000) != 0;
    const size_t maxNameLength = (version & 0x400) ? 255 : 31;
    const auto readName = [&] { return readExrName(stream, maxNameLength, path); };
    for (bool anotherPart = true; anotherPart;) {
        bool attributes = false;
        for (std::string name = readName(); !name.empty(); name = readName()) {
            attributes = true;
            const std::string type = readName();
            const int64_t size = readExrInt32(stream);
            const uint64_t left = fileBytes - std::min<uint64_t>(stream.tellg(), fileBytes);
            if (size < 0 || uint64_t(size) > left) {
                refuseExrHeader(path, "header attribute '" + name + "' declares " + std::to_string(size) +
                                          " bytes, more than the " + std::to_string(left) + " left in the file");
            }
            checkExrValue(stream, name, type, size, maxNameLength, path);
        }
        anotherPart = multiPart && attributes;
    }
    stream.seekg(0);
}

ImageChannels readExrStream(Imf::IStream& stream, uint64_t fileBytes, const fs::path& path,
                            const std::vector<std::string>* wanted) {
    checkExrHeaders(stream, fileBytes, path);
    Imf::InputFile input(stream);
    const Imath::Box2i window = input.header().dataWindow();
    ImageChannels image;
    image.source = path.string();
    image.names = wanted ? *wanted : channelNamesOf(input.header());
    checkExrSize(path, int64_t(window.max.x) - window.min.x + 1, int64_t(window.max.y) - window.min.y + 1,
                 image.names.size());
    image.width = window.max.x - window.min.x + 1;
    image.height = window.max.y - window.min.y + 1;
    image.data.resize(image.names.size());
    Imf::FrameBuffer frameBuffer;
    for (size_t k = 0; k < image.names.size(); ++k) {
        if (input.header().channels().findChannel(image.names[k]) == nullptr) {
            throw std::runtime_error("EXR file " + quotedPath(path) + " has no channel '" + image.names[k] + "'");
        }
        image.data[k].resize(image.pixelCount());
        // Any stored type (HALF, UINT, FLOAT) is converted to FLOAT by the library.
        frameBuffer.insert(image.names[k], Imf::Slice::Make(Imf::FLOAT, image.data[k].data(), window));
    }
    input.setFrameBuffer(frameBuffer);
    input.readPixels(window.min.y, window.max.y);
    return image;
}

// OpenEXR reports errors (missing file, not an EXR, truncated data) as Iex exceptions;
// turn them into the documented std::runtime_error that names the file. `open` makes the
// stream: from the file, or from bytes in memory, and says how many bytes it holds.
template <typename OpenStream>
ImageChannels readExrOrThrow(const fs::path& path, const std::vector<std::string>* wanted, OpenStream open) {
    try {
        uint64_t fileBytes = 0;
        auto stream = open(fileBytes);
        return readExrStream(*stream, fileBytes, path, wanted);
    } catch (const Iex::BaseExc& e) {
        throw std::runtime_error("cannot read EXR file " + quotedPath(path) + ": " + e.what());
    }
}

ImageChannels readExrFromFile(const fs::path& path, const std::vector<std::string>* wanted) {
    return readExrOrThrow(path, wanted, [&](uint64_t& fileBytes) {
        try {
            fileBytes = regularFileSize(path.string());   // before opening: a FIFO would block
        } catch (const SceneError& error) {
            throw std::runtime_error("cannot read EXR file " + quotedPath(path) + ": " + error.what());
        }
        return std::make_unique<Imf::StdIFStream>(path.c_str());
    });
}

}  // namespace

const std::vector<float>* ImageChannels::find(std::string_view name) const {
    const auto it = std::find(names.begin(), names.end(), name);
    return it == names.end() ? nullptr : &data[size_t(it - names.begin())];
}

const std::vector<float>& ImageChannels::at(std::string_view name) const {
    if (const std::vector<float>* values = find(name)) {
        return *values;
    }
    throw std::runtime_error("image " + (source.empty() ? std::string("(in memory)") : quotedPath(source)) +
                             " has no channel '" + std::string(name) + "'");
}

void ImageChannels::set(std::string name, std::vector<float> values) {
    if (values.size() != pixelCount()) {
        throw std::invalid_argument("channel '" + name + "' has " + std::to_string(values.size()) +
                                    " values, image has " + std::to_string(pixelCount()) + " pixels");
    }
    const auto it = std::find(names.begin(), names.end(), name);
    if (it != names.end()) {
        data[size_t(it - names.begin())] = std::move(values);
        return;
    }
    names.push_back(std::move(name));
    data.push_back(std::move(values));
}

namespace {

// One channel per component of a vec3 buffer, named names[0..2].
void setComponents(ImageChannels& image, const char* const (&names)[3], const std::vector<glm::vec3>& values) {
    for (int c = 0; c < 3; ++c) {
        std::vector<float> component(values.size());
        std::transform(values.begin(), values.end(), component.begin(), [c](const glm::vec3& v) { return v[c]; });
        image.set(names[c], std::move(component));
    }
}

}  // namespace

void setRadiance(ImageChannels& image, const std::vector<glm::vec3>& radiance) {
    setComponents(image, {channel::R, channel::G, channel::B}, radiance);
}

std::optional<std::vector<glm::vec3>> radianceOf(const ImageChannels& image) {
    const std::vector<float>*r = image.find(channel::R), *g = image.find(channel::G), *b = image.find(channel::B);
    if (!r || !g || !b) return std::nullopt;
    std::vector<glm::vec3> radiance(r->size());
    for (size_t k = 0; k < radiance.size(); ++k) radiance[k] = {(*r)[k], (*g)[k], (*b)[k]};
    return radiance;
}

void setGBuffer(ImageChannels& image, const GBuffer& gbuffer) {
    if (image.names.empty()) {
        image.width = gbuffer.width;
        image.height = gbuffer.height;
    }
    setComponents(image, {channel::Px, channel::Py, channel::Pz}, gbuffer.position);
    setComponents(image, {channel::Nx, channel::Ny, channel::Nz}, gbuffer.normal);
    setComponents(image, {channel::Nsx, channel::Nsy, channel::Nsz}, gbuffer.shadingNormal);
    image.set(channel::hit, std::vector<float>(gbuffer.hit.begin(), gbuffer.hit.end()));
    image.set(channel::depth, gbuffer.depth);
    const std::vector<glm::vec2>& offset = gbuffer.motion.pixelOffset;
    if (offset.empty()) return;
    std::vector<float> x(offset.size()), y(offset.size());
    for (size_t k = 0; k < offset.size(); ++k) x[k] = offset[k].x, y[k] = offset[k].y;
    image.set(channel::motionX, std::move(x));
    image.set(channel::motionY, std::move(y));
}

void writeExr(const fs::path& path, const ImageChannels& image) {
    try {
        checkWritable(image);
    } catch (const std::invalid_argument& e) {
        throw std::runtime_error("cannot write EXR file " + quotedPath(path) + ": " + e.what());
    }
    writeFileAtomically(path, [&](const fs::path& temporary) { writeExrFile(temporary, image); });
}

ImageChannels readExr(const fs::path& path) { return readExrFromFile(path, nullptr); }

ImageChannels readExr(const fs::path& path, const std::vector<std::string>& names) {
    return readExrFromFile(path, &names);
}

ImageChannels parseExr(const std::string& bytes, const fs::path& path) {
    return readExrOrThrow(path, nullptr, [&](uint64_t& fileBytes) {
        auto stream = std::make_unique<Imf::StdISStream>();
        stream->str(bytes);
        fileBytes = bytes.size();
        return stream;
    });
}

void writePng(const fs::path& path, int width, int height, const std::vector<uint8_t>& rgb) {
    if (width <= 0 || height <= 0 || rgb.size() != size_t(width) * size_t(height) * 3) {
        throw std::runtime_error("cannot write PNG file " + quotedPath(path) + ": " + std::to_string(rgb.size()) +
                                 " bytes for " + std::to_string(width) + " x " + std::to_string(height) +
                                 " RGB pixels");
    }
    writeFileAtomically(path, [&](const fs::path& temporary) {
        if (stbi_write_png(temporary.c_str(), width, height, 3, rgb.data(), width * 3) == 0) {
            throw std::runtime_error("stbi_write_png failed");
        }
    });
}

Image8 readImage8(const fs::path& path) {
    DecodedImage image = readImage(path.string(), 3, {ImageFormat::Png, ImageFormat::Jpeg});
    return {image.width, image.height, std::move(image.bytes)};
}

}  // namespace shadowlab
