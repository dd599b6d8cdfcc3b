// Prefiltered environment maps for glossy lobes (Heidrich and Seidel 1999, "Realistic,
// Hardware-accelerated Shading and Lighting"; the paper's fast local specular light, its
// section 3.1): for each reflection direction r, the lobe-weighted mean of the radiance,
//
//     P(r) = integral L(l) w(r . l) dl / integral w(r . l) dl,
//
// tabulated over r as a latitude-longitude map, and over the lobe's sharpness as a table of
// maps interpolated in its logarithm. Two lobes, each a function of c = r . l alone:
//
//   normalised Phong   w(c) = max(0, c)^n, shininess n >= 1; the BRDF ks (n + 2) / (2 pi) c^n
//                      (Lafortune and Willems 1994) reflects about ks (n + 2) / (n + 1) (N . r) P(r)
//                      (the lobe integrates to 2 pi / (n + 1) over the hemisphere about r);
//   GGX                w(c) = D(h) max(0, c), roughness alpha in (0, 1], h the half vector of
//                      r and l, D the GGX distribution (Walter et al. 2007): the environment
//                      half of the split sum (Karis 2013, "Real Shading in Unreal Engine 4"),
//                      which takes N = V = r (the other half is split_sum_table.h).
//
// A weighted mean, so a constant environment gives exactly its radiance, to rounding.
//
// The integral is a sum over a tiling of the sphere by texels of the map's pyramid
// (environment_pyramid.h), each weighted by w at its centre times its solid angle, refined
// where the midpoint rule could matter: a texel is split into its children while the
// weight's curvature across it, times its solid angle and its brightness (its brightest map
// texel, at least the map's mean), exceeds 10^-3 of the lobe's integral times the map's mean
// luminance. Near r the lobe is resolved by the map's own texels; far away, dim texels are
// taken coarse. Every texel of the sphere is counted exactly once, so nothing is truncated
// and a sun anywhere is seen at its full power; a few thousand texels per r instead of the
// map's half million.
//
// The output map holds P at its texels' centres (read it with samplePrefiltered, bilinear) and
// is finer for sharper lobes: 3 texels per sigma along a meridian, 2:1 like the input, at least
// 16 x 8 and at most the input's size. Rows are computed in parallel, one task each, so the
// same bits for any thread count.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "shading/environment/environment_map.h"
#include "shading/environment/environment_pyramid.h"

namespace shadowlab {

enum class GlossyLobe { NormalisedPhong, Ggx };

// The lobe's angular width sigma in radians, for a shininess (Phong) or a roughness (GGX).
double lobeWidth(GlossyLobe lobe, double parameter);

// Throws std::invalid_argument unless the parameter is a Phong shininess >= 1 or a GGX
// roughness in (0, 1], whose lobe is at least four of the map's texels wide (sigma >= 4 pi / H,
// so the map's own texels resolve it): shininess up to about 1600 on a 1024 x 512 map.
void checkLobe(GlossyLobe lobe, double parameter, const EnvironmentMap& map);

// P for one lobe (checkLobe first); the pyramid is buildPyramid(map).
EnvironmentMap prefilterLobe(const EnvironmentMap& map, const EnvironmentPyramid& pyramid, GlossyLobe lobe,
                             double parameter);

// Bilinear between texel centres (wrapping in azimuth, clamped at the poles' rows).
glm::dvec3 samplePrefiltered(const EnvironmentMap& prefiltered, const glm::dvec3& direction);

// A table of prefiltered maps over the lobe's parameter, ascending.
struct PrefilteredLobes {
    GlossyLobe lobe = GlossyLobe::NormalisedPhong;
    std::vector<double> parameters;
    std::vector<EnvironmentMap> maps;
};

// Shininess 1, 2, 4, ... or roughness 1, 1/sqrt 2, 1/2, ..., as far as checkLobe allows.
std::vector<double> defaultLobeLadder(GlossyLobe lobe, const EnvironmentMap& map);

// One map per parameter (each checked; duplicates dropped), on one pyramid.
PrefilteredLobes prefilterLobes(const EnvironmentMap& map, GlossyLobe lobe, std::vector<double> parameters);

// P at a direction for any parameter: an entry's own map where the table has it, otherwise
// the two neighbouring entries' samples interpolated linearly in log(parameter); clamped to
// the table's ends (callers check their materials against the range first).
glm::dvec3 lookupPrefiltered(const PrefilteredLobes& table, double parameter, const glm::dvec3& direction);

}  // namespace shadowlab
