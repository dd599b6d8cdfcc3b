// The radiance of every patch of the model (Gibson et al. 2003, section 3: "every patch with
// radiance is a potential source"). The paper reads it from the photographs; our built-in
// cases render their photograph from the model, so the radiance is rendered too, and with
// the same light: what a patch emits plus what it reflects of the emitting patches' direct
// light at its centre (one bounce, visibility by Embree rays against the model). Patches
// that reflect light become the secondary sources the source set may keep (section 4).
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "differential/patch_light.h"
#include "differential/scene/compositing_scene.h"
#include "shadows/reference/reference.h"

namespace shadowlab {

std::vector<glm::dvec3> patchRadiance(const PatchModel& model, const ReferenceVisibility& modelRays,
                                      const PatchSampling& sampling);

// The patches that emit or reflect anything, in patch order.
std::vector<uint32_t> radiantPatches(const PatchModel& model, const std::vector<glm::dvec3>& radiance);

}  // namespace shadowlab
