// The lookup of a spot or point light's virtual map (docs/virtual-shadow-maps.md;
// page_lookup.h for the sun's): each pixel reads the face and mip marking chose for it as
// a perspective shadow map of that mip's texels would be read (the shadow maps' receiver
// mapping and bias, shadow_bias.h, with the light at the apex, and their percentage-closer
// filters, pcf.h), each tap's texel clamped to the mip as a map clamps to its border, found
// through the page table in the physical pool. A tap in a page without memory (the pool
// overflowed) reads lit and its pixel is counted; a pixel in no face is lit, and counted.
#pragma once

#include <vector>

#include "scenes/scene.h"
#include "shading/gbuffer.h"
#include "shadows/maps/shadow_bias.h"
#include "shadows/virtual/mip_chain.h"
#include "shadows/virtual/page_lookup.h"
#include "shadows/virtual/page_marking.h"
#include "shadows/virtual/page_rendering.h"
#include "shadows/virtual/page_table.h"

namespace shadowlab::vsm {

// `light` decides which pixels it reaches (an area light as itself); the receivers are
// mapped from chain.apex.
LookupResult lookUpLocalPages(const GBuffer& g, const Light& light, const MipChain& chain, const BiasSettings& bias,
                              const PcfKernel& filter, const std::vector<PixelLevel>& levels, const PageTable& table,
                              const PagePool& pool);

}  // namespace shadowlab::vsm
