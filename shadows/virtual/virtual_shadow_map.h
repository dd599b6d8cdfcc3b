// The `virtual-shadow-map` technique (docs/virtual-shadow-maps.md): a sun's clipmap of
// pages, or a spot, point or area light's faces' mip chains of pages (mip_chain.h), marked
// from the G-buffer, rendered only where not already valid, kept across frames in the
// technique's history until a caster that moved or a move of the light invalidates them,
// and read with the shadow maps' bias.
#pragma once

#include "shadows/technique.h"

namespace shadowlab {

Technique virtualShadowMapTechnique();

}  // namespace shadowlab
