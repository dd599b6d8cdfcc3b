// The answer a composite is scored against: differential rendering with exact visibility
// (Debevec 1998), I_final = I_b - (I_noobj - I_obj). I_noobj and I_obj are the model lit by
// every radiant patch, each sampled by its strata (patch_light.h) with Embree visibility,
// without and with the object. They differ only where the object blocks a sample the model
// lets through, so the reference sums exactly those samples' light (the same strata, the
// same jitter, so the two renderings' noise cancels) rather than rendering both; a pixel on
// the object takes I_obj, the object lit by every patch with the model and itself in the
// way. A patch whose every segment from the pixel passes clear of the object's bounding
// sphere is skipped, which changes nothing.
#pragma once

#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "differential/composite.h"
#include "differential/preprocess.h"

namespace shadowlab {

// Denser than the photograph's by default.
inline PatchSampling referenceSampling() { return PatchSampling{8, 2, 0x7e1e5c0bea7ull}; }

// Linear radiance per pixel, object i placed by placements[i]. Throws std::invalid_argument
// for a placement that is not finite or a count that is not the objects'.
std::vector<glm::vec3> differentialReference(const DifferentialModel& model, const PreparedObject& object,
                                             std::span<const glm::mat4> placements,
                                             const PatchSampling& sampling = referenceSampling());

}  // namespace shadowlab
