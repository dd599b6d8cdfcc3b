#include "python/debug_readback.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace fs = std::filesystem;

namespace shadowlab::python {
namespace {

void readFolder(const fs::path& folder, const std::string& prefix, DebugReadback& into) {
    for (const fs::directory_entry& entry : fs::directory_iterator(folder)) {
        const fs::path& path = entry.path();
        const std::string name = prefix + path.stem().string();
        if (entry.is_directory()) readFolder(path, prefix + path.filename().string() + "/", into);
        else if (path.extension() == ".exr") into.buffers[name] = readExr(path);
        else if (path.extension() == ".png" && !fs::exists(fs::path(path).replace_extension(".exr")))
            into.pictures[name] = readImage8(path);
    }
}

}  // namespace

fs::path makeTemporaryDirectory() {
    std::string pattern = (fs::temp_directory_path() / "shadowlab-debug.XXXXXX").string();
    if (!mkdtemp(pattern.data()))
        throw std::runtime_error(pattern + ": cannot make a temporary directory: " + std::strerror(errno));
    return pattern;
}

DebugReadback readBackDebugBuffers(const fs::path& directory) {
    DebugReadback readback;
    try {
        readFolder(directory, "", readback);
    } catch (...) {
        fs::remove_all(directory);
        throw;
    }
    fs::remove_all(directory);
    return readback;
}

}  // namespace shadowlab::python
