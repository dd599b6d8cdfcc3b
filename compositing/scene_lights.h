// The scene's own lights (point, spot, directional, area) composited additively on top of
// the environment's light (DeCoro and Rusinkiewicz 2008, section 4): each shaded where it is
// visible, its V found by the technique's visibility method at full resolution.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "compositing/light_visibility.h"
#include "shadows/technique.h"

namespace shadowlab {

// Adds every light of in.scene() to `radiance` (one entry per pixel of in.gbuffer); returns
// the pixels shaded.
uint64_t addSceneLights(const ShadowInputs& in, LightVisibility& visibility, std::vector<glm::vec3>& radiance);

}  // namespace shadowlab
