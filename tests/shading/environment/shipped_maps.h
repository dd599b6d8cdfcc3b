// Where the environment tests find the shipped maps (scenes/environments, MANIFEST there).
#pragma once

#include <filesystem>

inline const std::filesystem::path kMaps = std::filesystem::path(SHADOWLAB_SOURCE_DIR) / "scenes" / "environments";
