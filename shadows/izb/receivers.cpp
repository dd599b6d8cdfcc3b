// Irregular z-buffer, stage 1: the camera samples that can receive light become the
// origins of shadow segments, exactly as the reference's shadow rays (reference.cpp), so
// the two answer the same question per pixel.
#include <algorithm>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "shading/lights.h"
#include "shadows/izb/izb.h"
#include "shadows/ray_offset.h"

namespace shadowlab::izb {

HomogeneousLight homogeneousLight(const Light& light) {
    if (light.type == LightType::Directional) return {glm::dvec3(light.direction), 0.0};
    return {glm::dvec3(light.position), 1.0};
}

Receivers gatherReceivers(const GBuffer& g, const Light& light, double diagonal, std::vector<float>& visibility) {
    const HomogeneousLight h = homogeneousLight(light);
    // The origin is rounded to float once, as the reference's ray origin is; a point light
    // nearer than the offset leaves no segment (tFar <= 0): seen, as in the reference.
    const auto segment = [&](size_t k, glm::dvec3& origin) {
        const double offset = shadowRayOffset(g.position[k], diagonal);
        origin = glm::dvec3(glm::vec3(glm::dvec3(g.position[k]) + offset * glm::dvec3(g.normal[k])));
        return h.w == 0.0 ? INFINITY : 1.0 - offset / glm::length(glm::dvec3(h) - origin);
    };
    // Decide per pixel in parallel (each writes only its own bytes), count the survivors in
    // pixel order, then fill each one's slot in parallel; a survivor's segment is computed
    // again there, which costs less than keeping an origin for every pixel.
    visibility.assign(g.pixelCount(), 0.0f);
    std::vector<uint8_t> keep(g.pixelCount(), 0);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, g.pixelCount(), 4096), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t k = r.begin(); k != r.end(); ++k) {
            if (!g.hit[k] || !lightReaches(light, g.position[k], g.normal[k])) continue;
            visibility[k] = 1.0f;
            glm::dvec3 origin;
            keep[k] = segment(k, origin) > 0.0;
        }
    });
    Receivers receivers;
    for (size_t k = 0; k < g.pixelCount(); ++k) {
        if (keep[k]) receivers.pixel.push_back(uint32_t(k));
    }
    receivers.origin.resize(receivers.pixel.size());
    receivers.tFar.resize(receivers.pixel.size());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, receivers.pixel.size(), 4096), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t n = r.begin(); n != r.end(); ++n) receivers.tFar[n] = segment(receivers.pixel[n], receivers.origin[n]);
    });
    return receivers;
}

}  // namespace shadowlab::izb
