// Image files. OpenEXR's scanline files have row 0 of the data window at the top, which
// matches our pixel convention, so buffers are passed through without flipping; the same
// holds for PNG. Writes go through writeFileAtomically() (see image_io.h for why).
#include "shading/image_io.h"

#include <algorithm>
#include <atomic>
#include <fstream>
#include <stdexcept>

#include <unistd.h>

#include <Iex.h>
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <stb_image_write.h>

#include "raster/fixed_point.h"
#include "scenes/scene_limits.h"

namespace shadowlab {
namespace fs = std::filesystem;

namespace {

std::string quoted(const fs::path& path) { return "'" + path.string() + "'"; }

// A name no other writer uses: the same directory (so rename() stays within one file
// system), hidden, and unique per process and per call.
fs::path temporaryPathFor(const fs::path& path) {
    static std::atomic<uint64_t> counter{0};
    std::string name(1, '.');
    name += path.filename().string();
    name += ".tmp." + std::to_string(::getpid()) + "." + std::to_string(counter.fetch_add(1));
    return path.parent_path() / name;
}

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
        throw std::runtime_error("EXR file " + quoted(path) + ": its data window is " + std::to_string(width) + " x " +
                                 std::to_string(height) + " pixels; images must be 1.." + std::to_string(raster::kMaxViewport) +
                                 " on a side");
    }
    if (channels > kMaxImageChannels) {
        throw std::runtime_error("EXR file " + quoted(path) + ": " + std::to_string(channels) + " channels, more than " +
                                 std::to_string(kMaxImageChannels));
    }
}

ImageChannels readExrFile(const fs::path& path, const std::vector<std::string>* wanted) {
    Imf::InputFile input(path.c_str());
    const Imath::Box2i window = input.header().dataWindow();
    ImageChannels image;
    image.source = path.string();
    image.names = wanted ? *wanted : channelNamesOf(input.header());
    checkExrSize(path, int64_t(window.max.x) - window.min.x + 1, int64_t(window.max.y) - window.min.y + 1, image.names.size());
    image.width = window.max.x - window.min.x + 1;
    image.height = window.max.y - window.min.y + 1;
    image.data.resize(image.names.size());
    Imf::FrameBuffer frameBuffer;
    for (size_t k = 0; k < image.names.size(); ++k) {
        if (input.header().channels().findChannel(image.names[k]) == nullptr) {
            throw std::runtime_error("EXR file " + quoted(path) + " has no channel '" + image.names[k] + "'");
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
// turn them into the documented std::runtime_error that names the file.
ImageChannels readExrOrThrow(const fs::path& path, const std::vector<std::string>* wanted) {
    try {
        return readExrFile(path, wanted);
    } catch (const Iex::BaseExc& e) {
        throw std::runtime_error("cannot read EXR file " + quoted(path) + ": " + e.what());
    }
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
    throw std::runtime_error("image " + (source.empty() ? std::string("(in memory)") : "'" + source + "'") +
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

void setRadiance(ImageChannels& image, const std::vector<glm::vec3>& radiance) {
    const char* names[3] = {channel::R, channel::G, channel::B};
    for (int c = 0; c < 3; ++c) {
        std::vector<float> values(radiance.size());
        std::transform(radiance.begin(), radiance.end(), values.begin(),
                       [c](const glm::vec3& v) { return v[c]; });
        image.set(names[c], std::move(values));
    }
}

void setGBuffer(ImageChannels& image, const GBuffer& gbuffer) {
    if (image.names.empty()) {
        image.width = gbuffer.width;
        image.height = gbuffer.height;
    }
    const char* positionNames[3] = {channel::Px, channel::Py, channel::Pz};
    const char* normalNames[3] = {channel::Nx, channel::Ny, channel::Nz};
    for (int c = 0; c < 3; ++c) {
        std::vector<float> p(gbuffer.pixelCount()), n(gbuffer.pixelCount());
        for (size_t k = 0; k < gbuffer.pixelCount(); ++k) {
            p[k] = gbuffer.position[k][c];
            n[k] = gbuffer.normal[k][c];
        }
        image.set(positionNames[c], std::move(p));
        image.set(normalNames[c], std::move(n));
    }
    image.set(channel::hit, std::vector<float>(gbuffer.hit.begin(), gbuffer.hit.end()));
    image.set(channel::depth, gbuffer.depth);
}

void writeExr(const fs::path& path, const ImageChannels& image) {
    try {
        checkWritable(image);
    } catch (const std::invalid_argument& e) {
        throw std::runtime_error("cannot write EXR file " + quoted(path) + ": " + e.what());
    }
    writeFileAtomically(path, [&](const fs::path& temporary) { writeExrFile(temporary, image); });
}

ImageChannels readExr(const fs::path& path) { return readExrOrThrow(path, nullptr); }

ImageChannels readExr(const fs::path& path, const std::vector<std::string>& names) {
    return readExrOrThrow(path, &names);
}

void writePng(const fs::path& path, int width, int height, const std::vector<uint8_t>& rgb) {
    if (width <= 0 || height <= 0 || rgb.size() != size_t(width) * size_t(height) * 3) {
        throw std::runtime_error("cannot write PNG file " + quoted(path) + ": " + std::to_string(rgb.size()) +
                                 " bytes for " + std::to_string(width) + " x " + std::to_string(height) +
                                 " RGB pixels");
    }
    writeFileAtomically(path, [&](const fs::path& temporary) {
        if (stbi_write_png(temporary.c_str(), width, height, 3, rgb.data(), width * 3) == 0) {
            throw std::runtime_error("stbi_write_png failed");
        }
    });
}

void writeFileAtomically(const fs::path& path, const std::function<void(const fs::path&)>& write) {
    const fs::path temporary = temporaryPathFor(path);
    try {
        write(temporary);
        fs::rename(temporary, path);
    } catch (const std::exception& e) {
        std::error_code ignored;  // the temporary may not exist; nothing more to report
        fs::remove(temporary, ignored);
        throw std::runtime_error("cannot write " + quoted(path) + ": " + e.what());
    }
}

void writeTextFile(const fs::path& path, std::string_view text) {
    writeFileAtomically(path, [&](const fs::path& temporary) {
        std::ofstream out(temporary, std::ios::binary);
        out.write(text.data(), std::streamsize(text.size()));
        out.close();
        if (!out) {
            throw std::runtime_error("write failed");
        }
    });
}

}  // namespace shadowlab
