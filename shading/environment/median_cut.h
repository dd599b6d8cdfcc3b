// Sampling an environment map into N directional lights by median cut (Debevec, "A Median Cut
// Algorithm for Light Probe Sampling", SIGGRAPH 2005 poster): the map's texel grid is cut into
// N rectangles of about equal energy, and each becomes one light at its energy centroid
// carrying the whole rectangle's radiant power.
//
//   energy    of a texel: its luminance (Rec. 709) times its solid angle (environment_map.h),
//             so a texel near a pole, which covers little of the sphere, weighs little;
//   a cut     splits a region across its longer side on the sphere (its width in radians
//             scaled by the sine of its middle latitude, against its height in radians), at
//             the texel edge that splits the energy most nearly in half;
//   N lights  Debevec cuts every region k times for 2^k lights; any N comes from cutting, one
//             at a time, the region with the most energy that still has two texels along a
//             side (ties: the earlier region; a heap, so N up to the texel count stays
//             O(N log N) in choosing), so N = 2^k gives his regions when the halves stay
//             balanced, and the brightest parts get the most lights;
//   a light   its direction the energy-weighted mean of its texels' centre directions,
//             normalised (a region whose mean cancels to rounding, such as a uniform map's
//             one region, or of no energy: its centre texel's direction); its power, in
//             RGB, the region's integral of radiance over solid angle, sum L dOmega, so the
//             lights' total is the map's integral and a Lambert surface of normal n facing
//             light l receives the irradiance power_l max(0, n . d_l).
//
// Deterministic: one thread, a fixed order of cuts and sums.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "shading/environment/environment_map.h"

namespace shadowlab {

struct EnvironmentLight {
    glm::dvec3 direction{0.0, 1.0, 0.0};   // unit, towards the light (world space, rotation included)
    glm::dvec3 power{0.0};                 // RGB: the region's integral of L dOmega, the irradiance it gives at normal incidence
    double solidAngle = 0.0;               // of the region, sr
    glm::ivec2 first{0}, last{0};          // median cut: the region's texels, [first, last) in (i, j)
};

// Throws std::invalid_argument unless 1 <= count <= the map's texel count.
std::vector<EnvironmentLight> medianCutLights(const EnvironmentMap& map, int count);

// Each map texel's light (row-major), from the lights' rectangles, for drawing the regions.
std::vector<uint32_t> medianCutRegions(const EnvironmentMap& map, const std::vector<EnvironmentLight>& lights);

}  // namespace shadowlab
