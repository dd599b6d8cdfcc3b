// The light a patch of the model sends to a point (Gibson et al. 2003, section 5): the
// radiance transfer L_ij = rho_i B_j F_ij V_ij of a source patch j of radiance B_j to a
// receiving point i of reflectance rho_i, with F_ij the form factor of the whole patch
// (shading/form_factor.h, exact) and V_ij the share of the patch the point sees, estimated
// by Embree shadow rays to one jittered point in each of k x k strata of the patch. Every
// user of it, the transfers, the rendered photograph, the object's irradiance and the
// differential reference, asks the same question with a different idea of what blocks a
// ray, so the test is the caller's.
#pragma once

#include <cstdint>
#include <span>

#include <glm/glm.hpp>

#include "differential/scene/compositing_scene.h"
#include "shading/form_factor.h"
#include "shading/light_sampling.h"

namespace shadowlab {

// Strata per side of a patch: more on patches that emit (the bright primary sources,
// whose penumbrae the eye sees) than on those that only reflect.
struct PatchSampling {
    int emitterSamplesPerAxis = 2;
    int reflectorSamplesPerAxis = 1;
    uint64_t seed = 0x9b05688c2b3e6c1full;
    int samplesPerAxis(const Patch& patch) const {
        return patch.emitted == glm::dvec3(0.0) ? reflectorSamplesPerAxis : emitterSamplesPerAxis;
    }
};

// The form factor of patch p from x (unit normal n).
inline double patchFormFactor(const PatchModel& model, uint32_t p, const glm::dvec3& x, const glm::dvec3& n) {
    const std::array<glm::dvec3, 4> corners = model.corners(p);
    return pointToPolygonFormFactor(x, n, corners);
}

// The share of patch p's strata for which seen(point) holds, one jittered point per stratum
// drawn from `rng` (every stratum draws, so the points never depend on the answers).
template <class Seen>
double seenShare(const PatchModel& model, uint32_t p, int samplesPerAxis, Pcg32& rng, const Seen& seen) {
    int count = 0;
    for (int b = 0; b < samplesPerAxis; ++b) {
        for (int a = 0; a < samplesPerAxis; ++a) {
            const glm::dvec2 u = jitteredSample(a, b, samplesPerAxis, rng);
            count += seen(model.pointAt(p, u.x, u.y)) ? 1 : 0;
        }
    }
    return double(count) / double(samplesPerAxis * samplesPerAxis);
}

// The jitter of patch j's strata seen from point `pointId` (a pixel, a vertex, a probe):
// a stream of its own, so the points depend on neither the other patches nor the order.
// Each use numbers its points from 0, so pixel 7 and vertex 7 share their jitter; no two
// estimates that are compared with each other come from different uses.
inline Pcg32 strataRandom(const PatchSampling& sampling, uint64_t pointId, uint32_t j, size_t patchCount) {
    return Pcg32(sampling.seed, pointId * uint64_t(patchCount) + j);
}

// B_j F_j share_j: the irradiance over pi that patch j of radiance B_j sends to x (unit
// normal n); a diffuse surface of reflectance rho turns it into the radiance rho times it.
// No ray is cast to a patch x cannot see (F = 0), its own included.
template <class Seen>
glm::dvec3 patchTransfer(const PatchModel& model, const glm::dvec3& B, uint32_t j, const glm::dvec3& x,
                         const glm::dvec3& n, const PatchSampling& sampling, uint64_t pointId, const Seen& seen) {
    const double F = patchFormFactor(model, j, x, n);
    if (F == 0.0) return glm::dvec3(0.0);
    Pcg32 rng = strataRandom(sampling, pointId, j, model.patches.size());
    return B * (F * seenShare(model, j, sampling.samplesPerAxis(model.patches[j]), rng, seen));
}

// Their sum over the listed patches of radiance B.
template <class Seen>
glm::dvec3 gatheredRadiance(const PatchModel& model, std::span<const glm::dvec3> B, std::span<const uint32_t> sources,
                            const glm::dvec3& x, const glm::dvec3& n, const PatchSampling& sampling, uint64_t pointId,
                            const Seen& seen) {
    glm::dvec3 sum(0.0);
    for (const uint32_t j : sources) sum += patchTransfer(model, B[j], j, x, n, sampling, pointId, seen);
    return sum;
}

}  // namespace shadowlab
