// The `backprojection` technique: per receiver, the shadow map's texels in the light's
// footprint back-projected onto the area light, the hidden samples of the light set in a
// bitmask (Guennebaud, Barthe and Paulin 2006; Schwarz and Stamminger 2007; RTR 4th ed.,
// 7.6). Stages: occluder_patches (which texels or hierarchy nodes occlude), surface_joins
// (which neighbours lie on one surface, once per frame), back_projection (onto the light,
// gaps closed by shared corners), light_bitmask (the light's samples), light_plot (a chosen
// pixel's patches drawn on the light). docs/accurate-soft-shadows.md.
#pragma once

#include "shadows/technique.h"

namespace shadowlab {

Technique backprojectionTechnique();

}  // namespace shadowlab
