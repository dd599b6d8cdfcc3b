// Projecting the occluders' texture onto the receivers (RTR 4th ed., section 7.2): each
// receiver pixel's surface point P goes through the texture's matrix to a texel, and is in
// shadow where an occluder covers that texel. Nothing is compared in depth, which is the
// method and its failures at once: a receiver between the light and an occluder is shadowed
// all the same (the shadow "cast backward"), and only the chosen receivers are shadowed
// (an occluder never shadows itself or another occluder).
//
// V per pixel: 0 outside a spot's cone (no light arrives, the V convention), else 0 on a
// receiver whose texel is covered, else 1, on every other surface too (as planar shadows
// leave the sides turned from the light to the shading's N.L). A receiver point behind a
// point or spot light's plane (w <= 0) or outside the texture is lit: the light sees no
// occluder there.
#pragma once

#include <cstdint>
#include <vector>

#include "shadows/projected/occluder_texture.h"
#include "shadows/technique.h"

namespace shadowlab {

struct ProjectedShadow {
    std::vector<float> visibility;      // V per pixel
    std::vector<float> receiverMask;    // 1 where the pixel's surface is a receiver, else 0
    size_t receiverPixels = 0, shadowedPixels = 0;
};

// `receiving` is indexed like Scene::instances; threads own rows, so the result does not
// depend on their number.
ProjectedShadow projectOntoReceivers(const GBuffer& g, const WorldGeometry& world,
                                     const std::vector<uint8_t>& receiving, const Light& light,
                                     const OccluderTexture& texture);

}  // namespace shadowlab
