// Shadow-map ray tracing towards a spot, point or area light through its virtual map's mip
// chains (docs/virtual-shadow-maps.md): the sun's method (smrt.h) along the rays of
// local_ray_samples.h. A sample is behind the stored surface where its window depth in its
// face is deeper than the texel's; the depth history (DepthHistory) runs in metres from the
// apex, the stored surface taken on the sample's own beam, d_stored / d_sample times the
// sample's distance (d: along the face's axis, from the face's window depth), and a step
// across is the chord between two samples' beams at the later one's distance. A ray that
// leaves every face ends as its last sample left it. V = the fraction of rays not hit; a
// point or spot light (no area) sends every ray to the apex: the hard lookup's shadow, with
// its contact detail where the history finds an occluder's edge.
//
// A read in a page without memory is counted and ends the ray unhit (lit, as the hard
// lookup reads a missing page). Deterministic: per pixel, a fixed PCG32 stream.
#pragma once

#include <vector>

#include "shadows/virtual/local_ray_samples.h"
#include "shadows/virtual/page_lookup.h"
#include "shadows/virtual/smrt.h"

namespace shadowlab::vsm {

// V per pixel from `smrt.rays` rays (at least 1); marking must have marked the samples'
// pages (markLocalRayPages).
SmrtResult traceLocalShadowMapRays(const GBuffer& g, const Light& light, const LocalRaySamples& samples,
                                   const SmrtSettings& smrt, const std::vector<PixelLevel>& levels,
                                   const PageTable& table, const PagePool& pool);

}  // namespace shadowlab::vsm
