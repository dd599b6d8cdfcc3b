// The shadow-casting lights (DeCoro and Rusinkiewicz 2008, section 2, step 1): the scene's
// environment sampled into N distant lights by median cut (shading/environment/median_cut.h),
// each carrying its region's integral of radiance, so that together they hold all of the
// map's light. N is the paper's illumination detail (section 2.2).
#pragma once

#include <vector>

#include "scenes/scene.h"
#include "shading/environment/median_cut.h"
#include "shadows/technique_params.h"

namespace shadowlab {

// The `lights` parameter, N, with its default.
ParamSpec environmentLightsParam(int defaultCount);

// The light as the shadow techniques see it: directional, towards the region's centroid,
// its irradiance at normal incidence the region's power.
Light directionalLight(const EnvironmentLight& light);

}  // namespace shadowlab
