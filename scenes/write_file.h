// Writing the program's output files, each whole or not at all: it is first written to a
// temporary file in the same folder and then renamed over the destination (rename() within
// one file system is atomic in POSIX), so a reader never sees a half-written file and a
// failed write leaves none behind (a process killed mid-write can leave a hidden temporary
// ".sl-XXXXXXXX", never a partial file). The temporary's name is short, so that any name a
// folder can hold (255 bytes) can be written, and its mode is a new file's (0666 less the
// umask), which the rename keeps. Through a symbolic link it writes the file the link names;
// a device or a pipe (/dev/null, a FIFO) it writes in place, since no rename may replace it.
// Errors are std::runtime_error naming the file.
#pragma once

#include <filesystem>
#include <functional>
#include <string_view>

namespace shadowlab {

// Runs write(temporaryPath), then renames the temporary file to `path`. If write throws or
// the rename fails, the temporary file is removed and std::runtime_error is thrown.
void writeFileAtomically(const std::filesystem::path& path,
                         const std::function<void(const std::filesystem::path&)>& write);

// A text file (JSON, CSV, SVG, HTML) written the same way.
void writeTextFile(const std::filesystem::path& path, std::string_view text);

}  // namespace shadowlab
