#include "differential/patch_radiance.h"

#include <tbb/parallel_for.h>

namespace shadowlab {

std::vector<uint32_t> radiantPatches(const PatchModel& model, const std::vector<glm::dvec3>& radiance) {
    std::vector<uint32_t> radiant;
    for (uint32_t p = 0; p < model.patches.size(); ++p) {
        if (radiance[p] != glm::dvec3(0.0)) radiant.push_back(p);
    }
    return radiant;
}

std::vector<glm::dvec3> patchRadiance(const PatchModel& model, const ReferenceVisibility& modelRays,
                                      const PatchSampling& sampling) {
    std::vector<glm::dvec3> emitted(model.patches.size());
    for (size_t p = 0; p < emitted.size(); ++p) emitted[p] = model.patches[p].emitted;
    const std::vector<uint32_t> emitters = radiantPatches(model, emitted);
    std::vector<glm::dvec3> radiance(emitted);
    tbb::parallel_for(size_t(0), model.patches.size(), [&](size_t p) {
        const Patch& patch = model.patches[p];
        if (patch.reflectance == glm::dvec3(0.0)) return;
        const glm::dvec3 x = model.centre(uint32_t(p));
        const auto seen = [&](const glm::dvec3& q) {
            return modelRays.pointVisible(glm::vec3(x), glm::vec3(patch.normal), q);
        };
        radiance[p] += patch.reflectance * gatheredRadiance(model, emitted, emitters, x, patch.normal,
                                                            sampling, p, seen);
    });
    return radiance;
}

}  // namespace shadowlab
