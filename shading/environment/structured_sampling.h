// Sampling an environment map into N directional lights by structured importance sampling
// (Agarwal, Ramamoorthi, Belongie and Jensen, "Structured Importance Sampling of Environment
// Maps", SIGGRAPH 2003), the sampler DeCoro and Rusinkiewicz use (their section 3.1). The
// paper's text is not in the project's library; this follows its published outline (the
// abstract, and the algorithm as its authors' talk and later implementations describe it):
//
//   strata     the map is cut into layers of luminance at multiples of its standard
//              deviation sigma (solid-angle weighted): stratum j holds the cells with
//              j sigma <= Y < (j + 1) sigma, the last one everything brighter;
//   counts     stratum j gets samples in proportion to its importance Gamma_j = Y_j
//              dOmega_j^(1/4), Y_j its mean luminance and dOmega_j its solid angle (the
//              paper's metric, balancing the light's intensity against the variance that
//              occlusion adds over a large region), rounded by largest remainders to N in
//              all; with fewer samples than strata, the most important strata get one each;
//   placement  within a stratum, from the brightest stratum down, Hochbaum and Shmoys'
//              farthest-point clustering: the map's brightest cell first, then each time
//              the stratum's cell farthest in angle from every sample placed so far (those
//              of brighter strata included), which spreads the samples evenly over it;
//   regions    every cell belongs to its nearest sample (the sphere's Voronoi cells of the
//              samples), and the light is the sample's direction carrying its region's
//              integral of radiance, so the lights' powers sum to the map's integral and
//              the regions tile the sphere.
//
// Cells are the texels of the finest level of the map's pyramid (environment_pyramid.h) no
// wider than 256 (a finer one where that has fewer than 8 cells a sample), each the exact
// mean of the map over its region, so every sum here is an exact integral of the map. The
// work is O(N cells). Deterministic: one thread, a fixed order, ties to the lower index.
#pragma once

#include <cstdint>
#include <vector>

#include "shading/environment/environment_map.h"
#include "shading/environment/environment_pyramid.h"
#include "shading/environment/median_cut.h"

namespace shadowlab {

// `pyramid` is buildPyramid(map), which callers build once per map. Throws
// std::invalid_argument unless 1 <= count <= the map's texel count. `regionOfTexel`, if
// given, receives each map texel's light (row-major), for drawing the regions.
std::vector<EnvironmentLight> structuredLights(const EnvironmentMap& map, const EnvironmentPyramid& pyramid, int count,
                                               std::vector<uint32_t>* regionOfTexel = nullptr);

}  // namespace shadowlab
