// Reading files the user names, shared by every reader of the program (scenes, meshes,
// images, calibrations, paths, sweep results): the file's type is checked before it is
// opened, since opening a FIFO blocks until a writer comes and a device such as /dev/zero
// never ends, and no read goes past the size the file had when it was checked.
#pragma once

#include <cstdint>
#include <string>

#include "scenes/scene_limits.h"

namespace shadowlab {

// The size of the regular file at `path` (a symbolic link is followed). Throws SceneError
// naming the file for a missing one (MissingFileError), a directory, a FIFO, a socket or a device, or one
// larger than `maxBytes` (by default kMaxFileBytes, scene_limits.h).
uint64_t regularFileSize(const std::string& path, uint64_t maxBytes = kMaxFileBytes);

// The file's bytes, after regularFileSize's checks; throws SceneError naming the file and
// the reason if it cannot be read.
std::string readWholeFile(const std::string& path, uint64_t maxBytes = kMaxFileBytes);

}  // namespace shadowlab
