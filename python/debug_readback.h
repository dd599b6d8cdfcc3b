// A technique's intermediate buffers for Python (Frame.debug): the frame renders them into a
// temporary directory (FrameSettings::debugDir), read back here and the directory removed.
#pragma once

#include <filesystem>
#include <map>
#include <string>

#include "shading/image_io.h"

namespace shadowlab::python {

struct DebugReadback {
    // By file stem ("shadow-map-depth"), "lightK/" before it for light K of a frame of several
    // (lightDebugFolder()): each EXR's float channels (Y, or R G B).
    std::map<std::string, ImageChannels> buffers;
    // The pictures made for people alone, written as a PNG without an EXR (lights drawn on a map).
    std::map<std::string, Image8> pictures;
};

// A new empty directory in the system's temporary directory; std::runtime_error if none can be made.
std::filesystem::path makeTemporaryDirectory();

// Every buffer and picture in `directory` and its light folders; then removes the directory.
DebugReadback readBackDebugBuffers(const std::filesystem::path& directory);

}  // namespace shadowlab::python
