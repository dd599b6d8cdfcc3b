// The `virtual-shadow-map` technique's frame for a spot, point or area light (docs/virtual-
// shadow-maps.md): the clipmap's stages (virtual_shadow_map.cpp) through the light's faces'
// mip chains (mip_chain.h), an area light from its centre as a point light (as `shadow-map`
// treats it):
//   1. the chain (its faces and depth range) and what moved since the last frame invalidates
//      (local_invalidation.h); a light that moved or turned starts the table afresh;
//   2. the pages the pixels mark (local_marking.h);
//   3. memory for them and the list of those to render (page_table.h);
//   4. those pages drawn (local_page_rendering.h);
//   5. the lookup (local_lookup.h), or shadow-map ray tracing towards the light's area
//      (local_smrt.h), whose samples' pages step 2 marks too (local_ray_samples.h);
//   6. on request, the buffers (virtual_debug.h).
// The table, the pool and what the last frame saw are kept in the technique's history.
#pragma once

#include "shadows/maps/pcf.h"
#include "shadows/maps/shadow_bias.h"
#include "shadows/technique.h"
#include "shadows/virtual/clipmap.h"
#include "shadows/virtual/smrt.h"

namespace shadowlab::vsm {

struct LocalMapSettings {
    ClipmapSettings clipmap;   // its resolution and page texels; the levels are the sun's
    int poolPages = 1024;
    int lodBias = 0;
    BiasSettings bias = {};
    FilterSettings filter = {};
    SmrtSettings smrt = {};
};

ShadowOutputs runLocalVirtualMap(const ShadowInputs& in, const LocalMapSettings& s);

}  // namespace shadowlab::vsm
