// `soft-shadow-volumes`: penumbra wedges (Akenine-Möller and Assarsson 2002; Assarsson and
// Akenine-Möller 2003). See soft_shadow_volumes.cpp for the passes.
#pragma once

#include "shadows/technique.h"

namespace shadowlab {

Technique softShadowVolumeTechnique();

}  // namespace shadowlab
