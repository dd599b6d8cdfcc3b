// Where the environment tests find the shipped maps (assets/environments, LICENSE.md there).
#pragma once

#include <filesystem>

inline const std::filesystem::path kMaps = std::filesystem::path(SHADOWLAB_SOURCE_DIR) / "assets" / "environments";
