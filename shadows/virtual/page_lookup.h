// The hard lookup of a virtual shadow map (docs/virtual-shadow-maps.md): each pixel reads the
// level marking chose for it, as a shadow map of that level's texels would be read (the
// shadow maps' receiver mapping and bias, shadow_bias.h), the texel found through the page
// table in the physical pool. A pixel whose page has no memory (the pool overflowed) or
// that no level holds is lit, and counted.
#pragma once

#include <vector>

#include "scenes/scene.h"
#include "shading/gbuffer.h"
#include "shadows/maps/shadow_bias.h"
#include "shadows/virtual/page_marking.h"
#include "shadows/virtual/page_rendering.h"
#include "shadows/virtual/page_table.h"

namespace shadowlab::vsm {

struct LookupResult {
    std::vector<float> visibility;   // V per pixel
    size_t missingPixels = 0;        // lit for want of a page with memory
    size_t unleveledPixels = 0;      // lit: reached by the light but in no level's window
};

LookupResult lookUpPages(const GBuffer& g, const Light& sun, const LightFrame& frame, const ClipmapSettings& clipmap,
                         const DepthRange& range, const BiasSettings& bias, const std::vector<PixelLevel>& levels,
                         const PageTable& table, const PagePool& pool);

// The marking reach a bias needs on top of the filter's: normal offset moves the lookup up
// to normalOffsetTexels texels from the surface point's texel.
double biasReachTexels(const BiasSettings& bias);

}  // namespace shadowlab::vsm
