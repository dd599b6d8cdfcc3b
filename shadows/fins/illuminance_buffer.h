// The illuminance buffer of shadow fins (Cai et al. 2006, sections 3.4 and 4.2): the
// visibility of the disk light at every camera pixel, from the light-space maps of one layer
// after another.
//
// One layer (section 3.4). A pixel's surface point P, at distance L_r from the light's plane,
// starts from the layer's hard shadow map: 1 if lit, 0 if not (the bias of shadow_bias.h).
// Then the refined weight of the inner fin over P is added (inner fins remove shadow) and
// that of the outer fin subtracted (outer fins add shadow), and the sum is clamped to [0, 1].
// A fin counts only if P lies behind it, L_b < L_r. Refinement (eqs. 2, 4 and 5): the fin was
// built for the reference plane L_0, where its width is B_0, with weight s_0 = e (1 - t_0); on
// the real receiver its width is B_r, so
//     s_r = e + (B_0 / B_r) (s_0 - e),   B_0 / B_r = ((L_0 - L_b) / L_0) (L_r / (L_r - L_b)),
// e = 0.5 for fins (eq. 5), 1 for outer-only methods; clamped to [0, e]. The light's radius
// (or the smoothies' angular width) cancels in the ratio. Optionally s_r then falls off as a
// Bernstein cubic 3u^2 - 2u^3 of the position u in the penumbra instead of linearly ([Hai01],
// section 3.4): in both halves of the penumbra that is the same cubic of the weight itself.
//
// Many layers (section 4.2), near to far: where a layer's own result is lit the buffer keeps
// the previous layers' value, where it is umbra it takes the layer's (0), and in its
// penumbra the minimum of the two. The three cases are one rule, I_i = min(I_{i-1}, local_i).
// A layer whose objects and fins all lie behind P is lit at P (its depth tests say so), so
// each pixel's value comes from the layers in front of it, as section 4.3's shading of each
// triangle with its own layer's buffer does.
//
// Pixels are independent; chunks of 512 pixels run in parallel and no value is reduced across threads.
#pragma once

#include <cstdint>
#include <vector>

#include "raster/tile_kernels.h"
#include "shading/gbuffer.h"
#include "shadows/depth_map.h"
#include "shadows/fins/fin_geometry.h"
#include "shadows/fins/fin_maps.h"
#include "shadows/fins/illuminance_kernel.h"

namespace shadowlab {

enum class Falloff { Linear, Bernstein };

struct IlluminanceSettings {
    LightPlane light;
    LightView view;                 // the full frustum the penumbra maps were drawn with
    double referenceDistance = 0.0; // L_0
    float edgeWeight = 0.5f;
    Falloff falloff = Falloff::Linear;
    raster::SimdLevel simd = raster::SimdLevel::Scalar;
};

// One layer's maps; inner is null for outer-only methods. The hard map is drawn with the
// slope-scaled bias (polygonOffsetFor(BiasSettings{})), so receivers are compared where
// they are.
struct LayerMaps {
    const DepthMap& hard;
    const PenumbraMap* inner;
    const PenumbraMap& outer;
};

// What the place kernel needs of a layer's hard map and the light (illuminance_kernel.h).
fins::PlaceConstants placeConstants(const DepthMap& hard, const LightPlane& light);

class IlluminanceBuffer {
public:
    // lit: per pixel, 1 where a surface faces the light's centre (dot(N, c - P) > 0, as in
    // the reference), else 0 (V = 0 there).
    IlluminanceBuffer(const GBuffer& gbuffer, const std::vector<uint8_t>& lit);

    // I = min(I, local) at every pixel, through the kernels of illuminance_kernel.h.
    void combineLayer(const LayerMaps& maps, const IlluminanceSettings& settings);

    const std::vector<float>& values() const { return values_; }

private:
    const GBuffer& gbuffer_;
    std::vector<float> values_;
};

}  // namespace shadowlab
