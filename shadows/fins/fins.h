// Soft shadows of a disk light from fins on silhouette edges, three techniques on one
// mechanism (see fins.cpp):
//   `fins`           multi-layered shadow fins (Cai, Jia, Wang, Hu and Martin 2006);
//   `smoothies`      outer primitives of one global angular size (Chan and Durand 2003);
//   `penumbra-maps`  outer primitives sized by the light (Wyman and Hansen 2003).
#pragma once

#include "shadows/technique.h"

namespace shadowlab {

Technique finsTechnique();
Technique smoothiesTechnique();
Technique penumbraMapsTechnique();

}  // namespace shadowlab
