// The synthetic object's light (Gibson et al. 2003, section 9: the object is shaded from an
// irradiance volume, Greger et al. 1998): probes on a regular grid over the box the object
// moves through, each the incident radiance of every radiant patch projected onto the nine
// spherical harmonics of order 2 (Ramamoorthi and Hanrahan 2001; the patches' strata as
// point samples of solid angle, visibility by Embree rays against the model, so the desk
// shades an object beneath it), kept as the irradiance coefficients A_l L_lm. A point gets
// the trilinear blend of its eight probes, evaluated at its normal.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "differential/patch_light.h"
#include "scenes/bounds.h"
#include "shading/environment/spherical_harmonics.h"
#include "shadows/reference/reference.h"

namespace shadowlab {

struct IrradianceVolume {
    Aabb bounds;                                     // the probes' lattice (their outer centres)
    glm::ivec3 probes{1};                            // per axis
    std::vector<ShCoefficients> irradiance;          // per probe, x fastest
    // The light gathered at x for normal n, over pi (what patch_light.h's gatheredRadiance
    // sums), x clamped into the box; never negative.
    glm::dvec3 at(const glm::dvec3& x, const glm::dvec3& n) const;
};

// Throws std::invalid_argument for a spacing that is not positive and finite or gives over
// 10^6 probes, or a box that is not finite.
IrradianceVolume buildIrradianceVolume(const PatchModel& model, const std::vector<glm::dvec3>& radiance,
                                       const ReferenceVisibility& modelRays, const Aabb& bounds, double spacing,
                                       const PatchSampling& sampling);

}  // namespace shadowlab
