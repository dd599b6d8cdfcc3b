// Irregular z-buffer, stage 1: the camera samples that can receive light become the
// origins of shadow segments, exactly as the reference's shadow rays (reference.cpp), so
// the two answer the same question per pixel.
#include <algorithm>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "shading/lights.h"
#include "shadows/izb.h"
#include "shadows/reference.h"

namespace shadowlab::izb {
namespace {

// Whether the light can reach P at all: in front of its surface (dot(N, L - P) > 0, the V
// convention) and, for a spot light, inside the cone. Points failing it get V = 0 untested.
bool canReceive(const Light& light, const HomogeneousLight& h, const glm::vec3& P, const glm::vec3& N) {
    const glm::dvec3 towardsLight = glm::dvec3(h) - h.w * glm::dvec3(P);
    if (!(glm::dot(glm::dvec3(N), towardsLight) > 0.0)) return false;
    return light.type != LightType::Spot || insideSpotCone(light, P);
}

}  // namespace

HomogeneousLight homogeneousLight(const Light& light) {
    if (light.type == LightType::Directional) return {glm::dvec3(light.direction), 0.0};
    return {glm::dvec3(light.position), 1.0};
}

Receivers gatherReceivers(const GBuffer& g, const Light& light, double diagonal, std::vector<float>& visibility) {
    const HomogeneousLight h = homogeneousLight(light);
    visibility.assign(g.pixelCount(), 0.0f);
    // Decide per pixel in parallel (each writes only its own byte), then keep the survivors
    // in pixel order.
    std::vector<uint8_t> keep(g.pixelCount(), 0);
    std::vector<double> tFar(g.pixelCount(), 0.0);
    std::vector<glm::dvec3> origin(g.pixelCount());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, g.pixelCount(), 4096), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t k = r.begin(); k != r.end(); ++k) {
            if (!g.hit[k] || !canReceive(light, h, g.position[k], g.normal[k])) continue;
            visibility[k] = 1.0f;
            // The origin is rounded to float once, as the reference's ray origin is.
            const double offset = shadowRayOffset(g.position[k], diagonal);
            origin[k] = glm::dvec3(glm::vec3(glm::dvec3(g.position[k]) + offset * glm::dvec3(g.normal[k])));
            // A point light nearer than the offset leaves no segment: seen, as in the reference.
            tFar[k] = h.w == 0.0 ? INFINITY : 1.0 - offset / glm::length(glm::dvec3(h) - origin[k]);
            keep[k] = tFar[k] > 0.0;
        }
    });
    Receivers receivers;
    for (size_t k = 0; k < g.pixelCount(); ++k) {
        if (!keep[k]) continue;
        receivers.pixel.push_back(uint32_t(k));
        receivers.origin.push_back(origin[k]);
        receivers.tFar.push_back(tFar[k]);
    }
    return receivers;
}

}  // namespace shadowlab::izb
