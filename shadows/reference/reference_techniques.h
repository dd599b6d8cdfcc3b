// The techniques every other one is measured against: `none` (no shadows, the upper bound
// of light), `reference` (exact hard shadows of a light's centre) and `reference-soft`
// (the exact visible fraction of an area light), all by Embree rays (reference.h).
#pragma once

#include "shadows/technique.h"

namespace shadowlab {

Technique unshadowedTechnique();
Technique referenceTechnique();
Technique softReferenceTechnique();

}  // namespace shadowlab
