// The light's view of the occluders (RTR 4th ed., section 7.2: the occluder is rendered
// "from the light's point of view" into the texture): a perspective frustum with its apex
// at a point or spot light, aimed at the centre of the occluders' bounding box, or an
// orthographic box along a directional light, its sides and depth range bounding every
// occluder vertex. The texture's texels are spent on the occluders alone, whatever the
// camera sees; a receiver outside the view gets no shadow, which is right, since no
// occluder lies between it and the light. Depth only bounds the drawing: the texture
// keeps none, so an occluder farther from the light than a receiver is drawn all the same
// (the shadow "cast backward").
#pragma once

#include <cstdint>
#include <span>

#include "scenes/scene.h"
#include "shadows/light_view.h"

namespace shadowlab {

// Throws std::invalid_argument when the occluders reach beside or behind a point or spot
// light (no frustum holds them) or enclose it. `occluders` must not be empty.
LightView fitOccluderView(const WorldGeometry& casters, std::span<const uint32_t> occluders, const Light& light,
                          int resolution);

}  // namespace shadowlab
