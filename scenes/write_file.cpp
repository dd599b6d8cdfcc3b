#include "scenes/write_file.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include <unistd.h>

#include "scenes/error_text.h"

namespace shadowlab {
namespace fs = std::filesystem;
namespace {

// A new empty file beside `path`, with a short name of its own (mkstemp's six letters).
fs::path temporaryPathFor(const fs::path& path) {
    std::string pattern = (path.parent_path() / ".sl-XXXXXX").string();
    const int descriptor = ::mkstemp(pattern.data());
    if (descriptor < 0) throw std::runtime_error(std::string("cannot make a temporary file: ") + std::strerror(errno));
    ::close(descriptor);
    return pattern;
}

}  // namespace

void writeFileAtomically(const fs::path& path, const std::function<void(const fs::path&)>& write) {
    fs::path temporary;
    try {
        temporary = temporaryPathFor(path);
        write(temporary);
        fs::rename(temporary, path);
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
