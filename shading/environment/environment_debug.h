// The environment's intermediate buffers as latitude-longitude images of the map's size (row
// 0 the zenith), for people to look at and for checks: the spherical-harmonic reconstruction
// of the radiance, the irradiance it gives a white Lambert surface facing each direction, and
// the sampled lights drawn on the map.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "shading/environment/environment_map.h"
#include "shading/environment/median_cut.h"
#include "shading/environment/spherical_harmonics.h"
#include "shading/tonemap.h"

namespace shadowlab {

// sum_k c_k Y_k at each texel's centre direction: with radiance coefficients, the nine-term
// reconstruction of the map (negative where it rings); with irradiance coefficients divided
// by pi (scale = 1 / pi), the radiance of a white Lambert surface whose normal is the texel's
// direction.
std::vector<glm::vec3> shImage(const EnvironmentMap& map, const ShCoefficients& coefficients, double scale = 1.0);

// The map tone mapped, each light's region outlined in grey (a texel whose right or lower
// neighbour belongs to another light; regionOfTexel from medianCutRegions or
// structuredLights) and its direction marked by a red 3 x 3 square: 8-bit sRGB, R G B per
// texel.
std::vector<uint8_t> lightsImage(const EnvironmentMap& map, const std::vector<EnvironmentLight>& lights,
                                 const std::vector<uint32_t>& regionOfTexel, const ToneMapOptions& tone);

}  // namespace shadowlab
