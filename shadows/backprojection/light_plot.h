// The debug view of one receiver's backprojection: the light in its own coordinates (a, b)
// with its sample grid (hidden samples dark, visible ones light, cells off a disk blank),
// the receiver's plane horizon, and every occluder patch projected onto it, outlined
// (`backprojection-light.svg`): what the bitmask saw.
#pragma once

#include <filesystem>
#include <vector>

#include <glm/glm.hpp>

#include "shadows/backprojection/light_bitmask.h"

namespace shadowlab {

// patches: four corners each, in (a, b).
void writeLightPlot(const std::filesystem::path& path, const LightGrid& grid, bool disk, const LightBitmask& hidden,
                    const std::vector<glm::vec2>& patches, int level);

}  // namespace shadowlab
