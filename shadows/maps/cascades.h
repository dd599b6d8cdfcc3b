// Cascaded shadow maps for a directional light (Real-Time Rendering, 4th ed., section
// 7.4.1, Figures 7.18-7.20; Engel 2006, Zhang et al. 2006 "parallel-split shadow maps"):
// the view frustum is cut at distances d_0 = n < d_1 < ... < d_c = f along the view axis
// and each slice gets its own orthographic map.
//
// Splits (z-partitioning):
//   logarithmic  d_i = n (f/n)^(i/c): a constant ratio r = (f/n)^(1/c), RTR eq. 7.5.
//   uniform      d_i = n + (f - n) i/c.
//   practical    lambda log + (1 - lambda) uniform (Zhang et al.'s blend, RTR 7.4.1).
// n and f are the camera's near and far planes, or with sample bounds the nearest and
// farthest receiver the camera sees (SDSM's min/max reduction, Lauritzen et al., RTR 7.4.1;
// a minimum and a maximum do not depend on the order, so any thread count gives them).
//
// Stability (RTR 7.4 "maintain the same relative texel beam locations in world space"):
// every cascade uses one light rotation that does not depend on the camera, a square box
// around the bounding sphere of its slice (whose size does not change as the camera turns
// or moves), and a box centre snapped to whole texels in light space. A camera move then
// shifts each map by whole texels, so a world point keeps its place in the texel grid.
// Sample bounds are rounded outwards to steps of 2^(1/8), so the slices keep their size,
// and snapping its effect, until the receivers' range changes by one step.
#pragma once

#include <vector>

#include "scenes/scene.h"
#include "shading/gbuffer.h"
#include "shadows/light_view.h"

namespace shadowlab {

enum class SplitScheme { Logarithmic, Uniform, Practical };

// count + 1 distances from n to f.
std::vector<double> cascadeSplits(double n, double f, int count, SplitScheme scheme, double lambda);

struct CascadeSettings {
    int count = 4;
    SplitScheme scheme = SplitScheme::Practical;
    double lambda = 0.75;
    bool sampleBounds = true;
    bool snap = true;
    int resolution = 2048;
    double marginTexels = 2.0;      // receivers stay this far inside (filter footprints, snapping)
};

struct Cascade {
    double nearDistance = 0.0, farDistance = 0.0;   // along the view axis
    bool hasReceivers = false;                      // false: no map is needed
    LightView view;
};

// The distance of P along the camera's view axis.
double viewDepth(const Camera& camera, const glm::dvec3& P);
// The cascade whose slice holds that distance (the first or last beyond the ends).
int cascadeOf(const std::vector<Cascade>& cascades, double depth);

// Throws std::invalid_argument for a light that is not directional or no receivers. `simd`
// picks light-view fitting's kernel (LightFitOptions::simd); every level gives the same views.
std::vector<Cascade> fitCascades(const Light& sun, const Camera& camera, const GBuffer& receivers,
                                 const WorldGeometry& world, const CascadeSettings& settings, raster::SimdLevel simd);

}  // namespace shadowlab
