#include "scenes/read_file.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "scenes/scene_file.h"

namespace shadowlab {

std::string readWholeFile(const std::string& path) {
    // A directory opens without error on Linux and only fails when read; say what it is.
    std::error_code ignored;
    if (std::filesystem::is_directory(path, ignored))
        throw SceneError(path + ": is a directory, not a file");
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in) throw SceneError(path + ": cannot open: " + std::strerror(errno));
    std::string bytes(size_t(in.tellg()), '\0');
    in.seekg(0);
    if (!in.read(bytes.data(), std::streamsize(bytes.size())))
        throw SceneError(path + ": cannot read: " + std::strerror(errno));
    return bytes;
}

}  // namespace shadowlab
