// Intermediate buffers of the shadow-map family (--debug-buffers DIR): each map's depths,
// the texel density seen from the camera (texels per screen pixel; 1 is mid grey, white is
// 2 or more, black is undersampled), and a false-colour image of which map served each
// pixel (cascades, cube faces) in the colours of RTR Figure 7.20.
#pragma once

#include <string>

#include "shading/gbuffer.h"
#include "shadows/debug_buffers.h"
#include "shadows/depth_map.h"
#include "shadows/maps/min_max_hierarchy.h"
#include "shadows/maps/shadow_lookup.h"

namespace shadowlab {

// The depths, black at the nearest drawn texel and white at 1 (nothing drawn).
void writeDepthMap(const DebugBuffers& debug, const std::string& name, const DepthMap& map);
void writeTexelDensity(const DebugBuffers& debug, const GBuffer& g, const ShadowLookup& lookup);
// DIR/<technique>-<name>.png: one colour per map index, darkened where V < 1.
void writeMapColouring(const std::filesystem::path& directory, const std::string& technique, const std::string& name,
                       const GBuffer& g, const ShadowLookup& lookup);

// Levels 2, 4 and 6 of a min/max hierarchy (those it has): `hierarchy-min-L` and
// `hierarchy-max-L`, each on the depth range of the whole map.
void writeMinMaxHierarchy(const DebugBuffers& debug, const MinMaxHierarchy& hierarchy);

}  // namespace shadowlab
