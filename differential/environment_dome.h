// A distant environment as patches of a compositing model (the outdoor and photograph
// cases): the map's upper half cut into columns x rows blocks, each a rectangle tangent to a
// dome of the given radius at the block's centre direction, facing in, with the block's mean
// radiance (each texel weighted by the solid angle it shares with the block) and exactly its
// solid angle: the dome holds the map's light above the horizon however finely it is cut,
// blocks finer than the texels included.
// Gibson et al. 2003 map a light probe's radiance onto the scene's distant patches the same
// way (section 3).
#pragma once

#include <vector>

#include "differential/scene/compositing_scene.h"
#include "shading/environment/environment_map.h"

namespace shadowlab {

// Throws std::invalid_argument for fewer than 4 columns or 1 row, or a radius that is not
// positive.
std::vector<PatchSurface> environmentDome(const EnvironmentMap& map, int columns, int rows, double radiusM);

}  // namespace shadowlab
