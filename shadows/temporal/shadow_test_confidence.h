// Shadow test confidence (Scherzer, Jeschke and Wimmer 2007, "Pixel-Correct Shadow Maps with
// Temporal Reprojection and Shadow Test Confidence", section 4): a shadow map's depth test
// is exact for a receiver at the centre of its texel, where the texel's depth was sampled,
// and grows less trustworthy towards the texel's sides. The confidence of pixel P's test is
//
//     c = 1 - 2 max(|x - x_c|, |y - y_c|)
//
// with (x, y) where P falls in the map (texel units) and (x_c, y_c) the centre of its texel:
// 1 at the centre, 0 on the texel's border. A map jittered by a sub-texel offset every frame
// brings every receiver near some texel's centre now and then; the history weighs each
// frame's test by c^m (confidence_blend.h), so the exact answer wins over frames.
#pragma once

#include <vector>

#include "scenes/scene.h"
#include "shading/gbuffer.h"
#include "shadows/depth_map.h"
#include "shadows/maps/shadow_bias.h"

namespace shadowlab {

// c per pixel of `g` in `map` (the light's, drawn for `light`), the receiver placed by
// `bias` as the lookup places it; 0 where hit = 0.
std::vector<float> shadowTestConfidence(const GBuffer& g, const DepthMap& map, const Light& light,
                                        const BiasSettings& bias);

}  // namespace shadowlab
