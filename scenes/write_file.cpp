#include "scenes/write_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <random>
#include <stdexcept>

#include <fcntl.h>
#include <unistd.h>

#include "scenes/error_text.h"

namespace shadowlab {
namespace fs = std::filesystem;
namespace {

// A new empty file beside `path`, made as a file written in place would be: mode 0666 less
// the umask (mkstemp's 0600 would leave every output unreadable to other users), under a
// short name no other writer holds (O_EXCL; a random suffix drawn again if it is taken).
fs::path temporaryPathFor(const fs::path& path) {
    std::random_device random;
    for (int attempt = 0; attempt < 64; ++attempt) {
        char name[16];
        std::snprintf(name, sizeof name, ".sl-%08x", unsigned(random()));
        const fs::path candidate = path.parent_path() / name;
        const int descriptor = ::open(candidate.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (descriptor >= 0) {
            ::close(descriptor);
            return candidate;
        }
        if (errno != EEXIST) throw std::runtime_error(std::string("cannot make a temporary file: ") + std::strerror(errno));
    }
    throw std::runtime_error("cannot make a temporary file: 64 random names were taken");
}

// The file the bytes are for: through a symbolic link to the file it names (renaming over
// the link would replace the link with a file of its own), the link kept where that file does
// not exist yet.
fs::path fileNamedBy(const fs::path& path) {
    std::error_code error;
    if (!fs::is_symlink(fs::symlink_status(path, error))) return path;
    const fs::path target = fs::canonical(path, error);
    return error ? path : target;
}

// Whether the destination is written in place: a device or a pipe (/dev/null, /dev/stdout, a
// FIFO), which no rename may replace and which has no half-written state to hide. A directory
// is refused.
bool writtenInPlace(const fs::path& path) {
    std::error_code error;
    const fs::file_status status = fs::status(path, error);
    if (!fs::exists(status)) return false;
    if (fs::is_directory(status)) throw std::runtime_error("it is a directory");
    return !fs::is_regular_file(status);
}

}  // namespace

void writeFileAtomically(const fs::path& path, const std::function<void(const fs::path&)>& write) {
    fs::path temporary;
    try {
        const fs::path destination = fileNamedBy(path);
        if (writtenInPlace(destination)) return write(destination);
        temporary = temporaryPathFor(destination);
        write(temporary);
        fs::rename(temporary, destination);
    } catch (const std::exception& e) {
        std::error_code ignored;   // the temporary may not exist; nothing more to report
        fs::remove(temporary, ignored);
        std::string message = "cannot write '";   // appended: GCC 12 warns wrongly of a chain of string +
        message += oneLine(path.string());
        message += "': ";
        message += e.what();
        throw std::runtime_error(message);
    }
}

void writeTextFile(const fs::path& path, std::string_view text) {
    writeFileAtomically(path, [&](const fs::path& temporary) {
        std::ofstream out(temporary, std::ios::binary);
        out.write(text.data(), std::streamsize(text.size()));
        out.close();
        if (!out) throw std::runtime_error("write failed");
    });
}

}  // namespace shadowlab
