// The penumbra's width per pixel, the radius of the penumbra-driven filter (penumbra.h),
// from the inputs SIGMA documents (NVIDIA NRD README: the distance to the occluder and
// the tangent of the light's angular radius): a receiver at distance d behind its occluder
// sees the light's edge sweep across a width w = d tan(theta), theta the light's angular
// radius seen from the occluder: for a sun atan(tanAngularRadius); for a local light of
// radius R, L from the receiver, tan(theta) = R / (L - d) (similar triangles). w projected
// to the screen, w f / z pixels at depth z, is the kernel's radius: 0 for a hard shadow,
// so its edge is kept as it is.
//
// A pixel whose own rays all reached the light knows no occluder: it takes the mean
// distance of the blocked rays within `searchRadius` pixels (SIGMA's inputs are as sparse;
// a penumbra's lit side must be filtered too), and none there means no penumbra near.
#pragma once

#include <vector>

#include "shadows/denoise/denoise_inputs.h"
#include "shadows/denoise/surface_features.h"

namespace shadowlab {

struct PenumbraRadiusSettings {
    int searchRadius = 4;       // pixels searched for an occluder distance
    float maxRadius = 16.0f;    // pixels: the kernel's cap
};

// Per G-buffer pixel, in pixels (0 where hit = 0 or no occluder near).
std::vector<float> penumbraRadius(const DenoiseInputs& in, const SurfaceFeatures& features,
                                  const PenumbraRadiusSettings& settings);

}  // namespace shadowlab
