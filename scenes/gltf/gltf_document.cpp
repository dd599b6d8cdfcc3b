#include "scenes/gltf/gltf_document.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <filesystem>
#include <string_view>

#include <nlohmann/json.hpp>

#include "scenes/error_text.h"
#include "scenes/image_file.h"
#include "scenes/read_file.h"
#include "scenes/scene_error.h"

namespace shadowlab {
namespace {

namespace fs = std::filesystem;

// The extensions this reader follows (docs/scene-format.md, "glTF files"); a file that
// requires any other is refused by name, one that only uses another is read without it.
constexpr std::array<std::string_view, 1> kReadExtensions{"KHR_lights_punctual"};

uint32_t littleEndian32(std::string_view bytes, size_t offset) {
    const auto* b = reinterpret_cast<const unsigned char*>(bytes.data() + offset);
    return uint32_t(b[0]) | uint32_t(b[1]) << 8 | uint32_t(b[2]) << 16 | uint32_t(b[3]) << 24;
}

// The binary container (glTF 2.0, section 4.4): a 12-byte header (magic, version 2, the
// file's length), a JSON chunk, then optionally one BIN chunk; each chunk an 8-byte header
// (length, type) and its bytes. Every length must agree with the file before tinygltf,
// which trusts some of them, reads the chunks.
void checkGlbChunks(std::string_view bytes, const std::string& path) {
    const auto fail = [&](const std::string& field, const std::string& problem) {
        throw SceneError(path + ": " + field + ": " + problem);
    };
    if (bytes.size() < 20) fail("header", "a .glb has at least 20 bytes (header and JSON chunk header)");
    if (littleEndian32(bytes, 4) != 2) fail("header.version", "must be 2, got " + std::to_string(littleEndian32(bytes, 4)));
    if (littleEndian32(bytes, 8) != bytes.size())
        fail("header.length", std::to_string(littleEndian32(bytes, 8)) + " but the file has " + std::to_string(bytes.size()) +
                                  " bytes");
    const uint64_t jsonLength = littleEndian32(bytes, 12);
    if (littleEndian32(bytes, 16) != 0x4E4F534Au) fail("chunks[0].type", "the first chunk must be JSON");
    if (jsonLength == 0 || 20 + jsonLength > bytes.size())
        fail("chunks[0].length", std::to_string(jsonLength) + " does not fit the file's " + std::to_string(bytes.size()) +
                                     " bytes");
    const uint64_t binStart = 20 + jsonLength;
    if (binStart == bytes.size()) return;
    if (binStart + 8 > bytes.size()) fail("chunks[1]", "its 8-byte header does not fit the file");
    const uint64_t binLength = littleEndian32(bytes, binStart);
    if (littleEndian32(bytes, binStart + 4) != 0x004E4942u) fail("chunks[1].type", "the second chunk must be BIN");
    if (binStart + 8 + binLength > bytes.size())
        fail("chunks[1].length", std::to_string(binLength) + " runs past the end of the file");
}

// tinygltf's file-system callbacks: every external file is `directory`/uri, read with
// the project's checked reader (scenes/read_file.h), and the uri must stay inside the
// folder: relative, without a ".." that leaves it.
struct FileAccess {
    std::string gltfPath, directory;
};

bool anyFileExists(const std::string&, void*) { return true; }   // the read says why it is not there
std::string unexpanded(const std::string& path, void*) { return path; }
bool noWrite(std::string*, const std::string&, const std::vector<unsigned char>&, void*) { return false; }

bool readExternalFile(std::vector<unsigned char>* out, std::string*, const std::string& joined, void* user) {
    const FileAccess& access = *static_cast<const FileAccess*>(user);
    // tinygltf joins directory and uri with a '/' unless the directory ends with one ("/").
    const std::string& directory = access.directory;
    const size_t prefix = directory.empty() ? 0 : directory.size() + (directory.ends_with('/') ? 0 : 1);
    const std::string uri = joined.substr(std::min(prefix, joined.size()));
    const fs::path normal = fs::path(uri).lexically_normal();
    const auto fail = [&](const std::string& problem) {
        throw SceneError(access.gltfPath + ": uri " + inQuotes(uri) + ": " + problem);
    };
    if (uri.empty() || normal.is_absolute() || (!normal.empty() && *normal.begin() == ".."))
        fail("must name a file inside the glTF file's folder");
    std::string bytes;
    try {
        bytes = readWholeFile(joined);
    } catch (const SceneError& error) {
        fail(error.what());
    }
    out->assign(bytes.begin(), bytes.end());
    return true;
}

// Every image, external, embedded or a data URI, decoded by the project's reader: PNG or
// JPEG, the formats glTF 2.0 allows (section 3.8.2), as RGBA bytes.
bool decodeGltfImage(tinygltf::Image* image, const int index, std::string*, std::string*, int, int,
                     const unsigned char* bytes, int size, void* user) {
    const FileAccess& access = *static_cast<const FileAccess*>(user);
    const std::string name = access.gltfPath + ": images[" + std::to_string(index) + "]";
    const DecodedImage decoded =
        decodeImage(std::string_view(reinterpret_cast<const char*>(bytes), size_t(size)), name, 4,
                    {ImageFormat::Png, ImageFormat::Jpeg});
    image->width = decoded.width;
    image->height = decoded.height;
    image->component = 4;
    image->bits = 8;
    image->pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
    image->image = decoded.bytes;
    return true;
}

// Checked on the JSON before tinygltf reads the rest, since tinygltf fails on what such an
// extension changes (a Draco mesh's accessors have no buffer view) before it could be named.
void checkRequiredExtensions(std::string_view json, const std::string& path) {
    const nlohmann::json document = nlohmann::json::parse(json, nullptr, false);
    if (!document.is_object() || !document.contains("extensionsRequired")) return;   // tinygltf says what is wrong
    const nlohmann::json& required = document["extensionsRequired"];
    for (size_t k = 0; required.is_array() && k < required.size(); ++k) {
        const std::string name = required[k].is_string() ? required[k].get<std::string>() : required[k].dump();
        if (std::ranges::find(kReadExtensions, name) == kReadExtensions.end())
            throw SceneError(path + ": extensionsRequired[" + std::to_string(k) + "]: " + inQuotes(name) +
                             " is not read here (read: KHR_lights_punctual)");
    }
}

}  // namespace

void GltfDocument::fail(const std::string& field, const std::string& problem) const {
    throw SceneError(path + ": " + field + ": " + problem);
}

GltfDocument parseGltfDocument(const std::string& bytes, const std::string& path) {
    FileAccess access{path, fs::path(path).parent_path().string()};
    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks({&anyFileExists, &unexpanded, &readExternalFile, &noWrite, &access});
    loader.SetImageLoader(&decodeGltfImage, &access);
    if (bytes.size() > uint64_t(UINT32_MAX)) throw SceneError(path + ": larger than 4 GiB, which glTF cannot address");
    GltfDocument document{path, {}};
    std::string error, warning;
    const bool binary = bytes.starts_with("glTF");
    if (binary) checkGlbChunks(bytes, path);
    checkRequiredExtensions(binary ? std::string_view(bytes).substr(20, littleEndian32(bytes, 12)) : std::string_view(bytes),
                            path);
    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
    const bool read = binary ? loader.LoadBinaryFromMemory(&document.model, &error, &warning, data,
                                                           unsigned(bytes.size()), access.directory)
                             : loader.LoadASCIIFromString(&document.model, &error, &warning, bytes.data(),
                                                          unsigned(bytes.size()), access.directory);
    // tinygltf's message, one line: what it names (a field, a buffer) is its own words. It
    // reports some errors (a property of the wrong type) and still returns true.
    if (!read || !error.empty()) {
        const std::string line = error.empty() ? "cannot read as glTF 2.0" : error.substr(0, error.find('\n'));
        throw SceneError(path + ": " + line);
    }
    return document;
}

GltfDocument readGltfDocument(const std::string& path) { return parseGltfDocument(readWholeFile(path), path); }

}  // namespace shadowlab
