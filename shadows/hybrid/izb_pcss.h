// The hybrid family: `izb-pcss`, the hybrid frustum-traced shadows of The Division (Story
// and Wyman, "HFTS: Hybrid Frustum-Traced Shadows in The Division", SIGGRAPH 2016 talk;
// Real-Time Rendering, 4th ed., section 7.9 and Figure 7.31). PCSS softens a shadow by the
// distance to its occluder but, through its bias, loses the shadow right at a contact and
// blurs a close occluder's edge with a far one's where their shadows overlap; the
// irregular z-buffer is exact but hard. So each pixel takes the hard shadow where its
// occluder is close (the exact penumbra is then narrower than a texel or so) and the soft
// one where it is far, blended between two occluder distances:
//   1. pcss          the map, blocker search and filter of shadows/filtered (pcss.h): the
//                    soft V and the mean blocker distance d_o per pixel;
//   2. izb           the `izb` technique itself, for the light's centre: the hard V;
//   3. blend weight  (blend_weight.cpp) w from the occluder's distance to the receiver;
//   4. blend         V = (1 - w) V_izb + w V_pcss.
#pragma once

#include <vector>

#include "shading/gbuffer.h"
#include "shadows/filtered/soft_shadow_map.h"
#include "shadows/technique.h"

namespace shadowlab {

Technique izbPcssTechnique();

// Occluder distances d_r - d_o (m, along the light's axis, from the receiver) at which the
// blend begins to leave the hard shadow and ends in the soft one.
struct BlendDistances {
    float hardBelowM = 0.1f;
    float softAboveM = 0.4f;
};

// Stage 3, per pixel: w = 0 (hard) up to hardBelowM, 1 (soft) from softAboveM, linear
// between. Where the search found no blocker (blockerDistance 0) the occluder, if any, is
// nearer than the map's bias lets it see: w = 0, so the exact shadow decides; w = 0 where
// there is no surface.
std::vector<float> blendWeights(const GBuffer& g, const SoftShadowMap& soft, const std::vector<float>& blockerDistance,
                                const BlendDistances& distances);

}  // namespace shadowlab
