// `shadow-volume`: stencil shadow volumes (Crow 1977; Heidmann 1991; Everitt and Kilgard
// 2002; RTR 4th ed., section 7.3). See shadow_volume.cpp for the passes.
#pragma once

#include "shadows/technique.h"
#include "shadows/volumes/stencil_pass.h"

namespace shadowlab {

// `shadow-volume` with typed settings, as another technique runs it per light (the
// environment techniques' LightVisibility); its `params` are not read.
ShadowOutputs runShadowVolume(const ShadowInputs& in, const StencilPassSettings& settings);

Technique shadowVolumeTechnique();

}  // namespace shadowlab
