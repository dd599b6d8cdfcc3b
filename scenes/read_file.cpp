#include "scenes/read_file.h"

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "scenes/scene_file.h"
#include "scenes/scene_limits.h"

namespace shadowlab {

std::string readWholeFile(const std::string& path) {
    // A directory opens without error on Linux and only fails when read; say what it is.
    std::error_code ignored;
    if (std::filesystem::is_directory(path, ignored))
        throw SceneError(path + ": is a directory, not a file");
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in) throw SceneError(path + ": cannot open: " + std::strerror(errno));
    const std::streamoff size = in.tellg();
    if (size < 0) throw SceneError(path + ": cannot tell its size (not a regular file?)");
    if (uint64_t(size) > kMaxFileBytes)
        throw SceneError(path + ": " + std::to_string(size) + " bytes, more than the " + std::to_string(kMaxFileBytes) +
                         " a file may have");
    std::string bytes(size_t(size), '\0');
    in.seekg(0);
    if (!in.read(bytes.data(), std::streamsize(bytes.size())))
        throw SceneError(path + ": cannot read: " + std::strerror(errno));
    return bytes;
}

}  // namespace shadowlab
