// Fast local illumination (the paper's section 2, step 3; DeCoro and Rusinkiewicz 2008): the
// light C a surface reflects from the whole environment, shadows ignored, from tables built
// once per map, so that its cost does not depend on the number of shadow-casting lights.
//
//   diffuse   albedo / pi * E(N), E the nine-coefficient irradiance (spherical_harmonics.h;
//             Ramamoorthi and Hanrahan 2001);
//   Phong     specular * (N . R) * P_n(R), R the mirror direction of wo about N and P_n the map
//             prefiltered for shininess n (prefiltered_lobe.h; Heidrich and Seidel 1999). Inside
//             the lobe N . l ~= N . R, with the lobe's mean cosine (n + 1) / (n + 2) folded into
//             the normalisation: exact under a constant environment seen along N, and exact to
//             first order in the lobe's width elsewhere while the lobe is above the horizon;
//   GGX       P_alpha(R) * (specular * A + B), the split sum (split_sum_table.h; Karis 2013):
//             exact under a constant environment, to the table's accuracy.
//
// Blinn-Phong has no lobe about a fixed direction to prefilter and is refused (the radiance
// cache of the paper's section 3.1 is its way, to come).
#pragma once

#include <glm/glm.hpp>

#include "scenes/scene.h"
#include "shading/environment/prefiltered_lobe.h"
#include "shading/environment/spherical_harmonics.h"
#include "shading/environment/split_sum_table.h"

namespace shadowlab {

struct LocalIllumination {
    ShCoefficients irradiance;   // irradianceOf(projectRadiance(map))
    PrefilteredLobes phong;      // empty unless a Phong material is shaded
    PrefilteredLobes ggx;        // empty unless a GGX material is shaded
    SplitSumTable splitSum;      // empty unless a GGX material is shaded
};

// The tables the materials need: SH irradiance always; a Phong table holding each Phong
// material's shininess; a GGX table holding each GGX material's roughness, and the split-sum
// table. Throws std::invalid_argument naming the material whose model is Blinn-Phong or whose
// lobe the map cannot resolve (checkLobe).
LocalIllumination buildLocalIllumination(const EnvironmentMap& map, const std::vector<Material>& materials);

// C at a surface point: outgoing radiance towards wo (unit, to the viewer) for the unit
// shading normal N, `albedo` the surface's there (shading/surface_albedo.h). Throws std::invalid_argument for a Blinn-Phong material, or for a Phong
// or GGX material when its table is empty.
glm::dvec3 unshadowedRadiance(const LocalIllumination& light, const Material& material, const glm::vec3& albedo,
                              const glm::dvec3& N, const glm::dvec3& wo);

}  // namespace shadowlab
