// `ray-traced`: shadows by N Embree rays per pixel towards the light, samples of an area
// light's area that change from frame to frame, and the occluder distance per pixel
// (shadow_rays.h): the noisy input that denoisers clean (docs/ray-traced-shadows.md).
#pragma once

#include "shadows/technique.h"

namespace shadowlab {

Technique rayTracedTechnique();

}  // namespace shadowlab
