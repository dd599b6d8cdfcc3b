// The screen-space family: `contact-shadows` (Sousa et al. 2011; Real-Time Rendering, 4th
// ed., section 7.10), a shadow map with a march over the camera's depth buffer that
// restores the short shadows next to their casters which the map's bias removes:
//   1. shadow map   the `shadow-map` technique itself, with its parameters (shadows/maps),
//                   its debug buffers in the folder contact-shadows-shadow-map;
//   2. march        each pixel's ray towards the light over the depth buffer
//                   (screen_march.h): the march mask;
//   3. combine      V = min(V_map, V_march) (contact_shadows.cpp says why);
// and the debug view of one pixel's march (march_plot.h).
#pragma once

#include "shadows/technique.h"

namespace shadowlab {

Technique contactShadowsTechnique();

}  // namespace shadowlab
