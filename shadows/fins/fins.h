// Soft shadows of a disk light from fins on silhouette edges, three techniques on one
// pipeline (fin_shadows.h), each in the file named after it:
//   `fins`           multi-layered shadow fins (Cai, Jia, Wang, Hu and Martin 2006), fins.cpp;
//   `smoothies`      outer primitives of one global angular size (Chan and Durand 2003),
//                    smoothies.cpp;
//   `penumbra-maps`  outer primitives sized by the light (Wyman and Hansen 2003),
//                    penumbra_maps.cpp.
#pragma once

#include "shadows/technique.h"

namespace shadowlab {

Technique finsTechnique();
Technique smoothiesTechnique();
Technique penumbraMapsTechnique();

}  // namespace shadowlab
