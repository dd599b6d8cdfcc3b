// The screen-space march of contact shadows (Sousa et al., "Secrets of CryENGINE 3
// Graphics Technology", SIGGRAPH 2011 course; Real-Time Rendering, 4th ed., section 7.10):
// the camera's depth buffer, already drawn for the frame, is read as a heightfield, and a
// ray from each pixel's surface point towards the light is marched over it (RTR 6.8.1). A
// sample that lies behind the surface the buffer holds at its pixel, by no more than the
// depth thickness, is inside that surface: the ray is blocked and the pixel shadowed.
//
// The buffer stores one surface per pixel, so the march knows neither what is off screen
// nor what hides behind the visible surfaces, nor how thick anything is: the thickness is
// a guess that every such technique has to make. Hence it only restores short shadows,
// next to their casters, and a shadow map does the rest (contact_shadows.cpp).
//
// Depth comparison: the G-buffer keeps each pixel's surface point P and normal N, so the
// buffer's depth is taken on the plane (P, N) where the camera's ray through the sample
// meets it, not at the pixel's centre: the receiver-plane comparison of RTR 7.5 (Figure
// 7.24, middle) in screen space. A plane then never shadows itself and no depth bias is
// needed; a curved surface is a plane within the pixel.
//
// Everything per sample is float arithmetic in a fixed order, written once as a vector
// kernel over the pixels of a row (march_kernel.h), compiled per instruction set; pixels are
// independent and rows run in parallel, so the mask is the same bytes for any thread count
// and SIMD level, and the plotted march of one pixel (march_plot.h) is the scalar build's.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "raster/tile_kernels.h"
#include "scenes/scene.h"
#include "shading/gbuffer.h"
#include "shadows/screen/march_kernel.h"

namespace shadowlab {

struct MarchSettings {
    float lengthM = 0.25f;      // how far towards the light the ray is marched, m
    int steps = 16;             // samples along it, evenly spaced, the last at lengthM
    float thicknessM = 0.05f;   // how far behind the buffer's surface a sample still counts as inside it, m
};

// One sample of a march, as the debug plot shows it.
struct MarchSample {
    float distanceM = 0.0f;      // along the ray from the surface point
    glm::vec2 pixel{0.0f};       // where it projects, pixel coordinates (centre of pixel i at i + 0.5)
    float sampleDepth = 0.0f;    // its view depth, m along the camera's axis
    float bufferDepth = 0.0f;    // the buffer's surface at that pixel, on the same camera ray; infinite: none
    bool occluded = false;
};

// Why a march ended.
enum class MarchEnd { Lit, Occluded, LeftScreen };

class ScreenMarch {
public:
    // The settings must be valid (MarchSettings' ranges in contact_shadows.cpp). The
    // G-buffer's normal must be 0 where no surface covers a pixel, as buildGBuffer leaves it.
    ScreenMarch(const GBuffer& g, const Camera& camera, const Light& pointLight, const MarchSettings& settings);

    // Every sample of pixel k's march towards the light, not stopping at the first occluded
    // one, until the ray leaves the screen or the steps reach the march length (or the
    // light, if nearer): the scalar kernel's trace.
    std::vector<MarchSample> samples(size_t k) const;

    // Per pixel: 0 where the march found an occluder, 1 elsewhere (also where the light
    // is behind the surface, which is the shadow map's to say), and why each march ended.
    struct Mask {
        std::vector<float> visibility;
        std::vector<uint8_t> end;   // MarchEnd per pixel; Lit where hit = 0
    };
    Mask mask(raster::SimdLevel simd) const;

private:
    const GBuffer& g_;
    Light light_;
    MarchConstants constants_;
    MarchSurfaces surfaces_;
};

}  // namespace shadowlab
