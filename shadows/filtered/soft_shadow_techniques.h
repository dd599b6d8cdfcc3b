// The soft-shadow family for area lights: `pcss` (percentage-closer soft
// shadows), the filtered maps `vsm`, `esm`, `evsm`, `msm` (one mechanism, four moment
// kinds; box or Gaussian blur or a summed-area table; fixed or PCSS width) and
// `multi-sample` (the average of hard shadow maps from points on the light). See
// pcss.cpp, filtered_shadow_map.cpp (with vsm.cpp, esm.cpp, evsm.cpp and msm.cpp) and
// multi_sample.cpp; docs/soft-shadows.md.
#pragma once

#include "shadows/filtered/moments.h"
#include "shadows/technique.h"

namespace shadowlab {

Technique pcssTechnique();
// `chs`, PCSS read on the min/max hierarchy's levels (contact_hardening.cpp).
Technique contactHardeningTechnique();
Technique filteredShadowMapTechnique(MomentKind kind);
Technique multiSampleTechnique();

}  // namespace shadowlab
