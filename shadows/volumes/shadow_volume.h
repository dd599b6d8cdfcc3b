// `shadow-volume`: stencil shadow volumes (Crow 1977; Heidmann 1991; Everitt and Kilgard
// 2002; RTR 4th ed., section 7.3). See shadow_volume.cpp for the passes.
#pragma once

#include "shadows/technique.h"

namespace shadowlab {

Technique shadowVolumeTechnique();

}  // namespace shadowlab
