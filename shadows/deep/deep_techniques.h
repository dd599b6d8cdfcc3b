// The volumetric shadow maps (Real-Time Rendering, 4th ed., section 7.8): shadows of
// translucent casters (tinted glass, hair) and density volumes (smoke), each storing per
// texel a different approximation of the transmittance curve of transmittance_curve.h.
#pragma once

#include "shadows/technique.h"

namespace shadowlab {

Technique colouredShadowMapTechnique();
Technique opacityShadowMapsTechnique();
Technique deepShadowMapsTechnique();
Technique adaptiveVolumetricShadowMapsTechnique();

}  // namespace shadowlab
