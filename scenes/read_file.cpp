#include "scenes/read_file.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "scenes/scene_error.h"
#include "scenes/scene_limits.h"

namespace shadowlab {
namespace {

const char* kindOf(std::filesystem::file_type type) {
    switch (type) {
        case std::filesystem::file_type::directory: return "a directory";
        case std::filesystem::file_type::fifo: return "a FIFO (named pipe)";
        case std::filesystem::file_type::socket: return "a socket";
        case std::filesystem::file_type::character: return "a character device";
        case std::filesystem::file_type::block: return "a block device";
        default: return "not a regular file";
    }
}

}  // namespace

uint64_t regularFileSize(const std::string& path, uint64_t maxBytes) {
    std::error_code error;
    const std::filesystem::file_status status = std::filesystem::status(path, error);
    if (status.type() == std::filesystem::file_type::not_found)
        throw MissingFileError(path + ": cannot open: " + error.message());
    if (error) throw SceneError(path + ": cannot open: " + error.message());
    if (status.type() != std::filesystem::file_type::regular)
        throw SceneError(path + ": is " + kindOf(status.type()) + ", not a file");
    const uint64_t size = std::filesystem::file_size(path, error);
    if (error) throw SceneError(path + ": cannot tell its size: " + error.message());
    if (size > maxBytes)
        throw SceneError(path + ": " + std::to_string(size) + " bytes, more than the " + std::to_string(maxBytes) +
                         " such a file may have");
    return size;
}

std::string readWholeFile(const std::string& path, uint64_t maxBytes) {
    const uint64_t size = regularFileSize(path, maxBytes);
    std::ifstream in(path, std::ios::binary);
    if (!in) throw SceneError(path + ": cannot open: " + std::strerror(errno));
    std::string bytes(size_t(size), '\0');
    if (!in.read(bytes.data(), std::streamsize(bytes.size())))
        throw SceneError(path + ": cannot read: " + std::strerror(errno));
    return bytes;
}

}  // namespace shadowlab
