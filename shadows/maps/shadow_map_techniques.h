// The shadow-map family: `shadow-map` (one map, or six cube faces for a point
// light among its receivers; optional LiSPSM warp for a directional light) and `csm`
// (cascaded shadow maps for a directional light). See shadow_map.cpp and csm.cpp.
#pragma once

#include "shadows/technique.h"

namespace shadowlab {

Technique shadowMapTechnique();
Technique cascadedShadowMapTechnique();

}  // namespace shadowlab
