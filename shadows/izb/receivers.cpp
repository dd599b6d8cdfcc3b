// Irregular z-buffer, stage 1: the camera samples that can receive light become the
// origins of shadow segments, exactly as the reference's shadow rays (reference.cpp), so
// the two answer the same question per pixel.
#include <algorithm>
#include <cmath>

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
    // The origin is rounded to float once, as the reference's ray origin is (so it is kept
    // as a float, exactly); a point light nearer than the offset leaves no segment
    // (tFar <= 0): seen, as in the reference.
    const auto segment = [&](size_t k, glm::vec3& origin) {
        const double offset = shadowRayOffset(g.position[k], diagonal);
        origin = glm::vec3(glm::dvec3(g.position[k]) + offset * glm::dvec3(g.normal[k]));
        return h.w == 0.0 ? INFINITY : 1.0 - offset / glm::length(glm::dvec3(h) - glm::dvec3(origin));
    };
    // Decide per pixel in parallel (each writes only its own bytes) and count the survivors
    // per chunk of pixels; an exclusive prefix sum over the chunks then gives each chunk the
    // first slot of its survivors, which it fills in parallel, in pixel order. A survivor's
    // segment is computed again there, which costs less than keeping an origin for every pixel.
    constexpr size_t kChunk = 4096;
    const size_t chunks = (g.pixelCount() + kChunk - 1) / kChunk;
    const auto chunkEnd = [&](size_t c) { return std::min(g.pixelCount(), (c + 1) * kChunk); };
    visibility.assign(g.pixelCount(), 0.0f);
    std::vector<uint8_t> keep(g.pixelCount(), 0);
    std::vector<uint32_t> first(chunks + 1, 0);
    tbb::parallel_for(size_t(0), chunks, [&](size_t c) {
        uint32_t kept = 0;   // counted locally: neighbouring chunks' counts share a cache line
        for (size_t k = c * kChunk; k < chunkEnd(c); ++k) {
            if (!g.hit[k] || !lightReaches(light, g.position[k], g.normal[k])) continue;
            visibility[k] = 1.0f;
            glm::vec3 origin;
            keep[k] = segment(k, origin) > 0.0;
            kept += keep[k];
        }
        first[c + 1] = kept;
    });
    for (size_t c = 0; c < chunks; ++c) first[c + 1] += first[c];
    Receivers receivers;
    receivers.pixel.resize(first[chunks]);
    receivers.origin.resize(first[chunks]);
    receivers.tFar.resize(first[chunks]);
    tbb::parallel_for(size_t(0), chunks, [&](size_t c) {
        uint32_t n = first[c];
        for (size_t k = c * kChunk; k < chunkEnd(c); ++k) {
            if (!keep[k]) continue;
            receivers.pixel[n] = uint32_t(k);
            receivers.tFar[n] = segment(k, receivers.origin[n]);
            ++n;
        }
    });
    return receivers;
}

}  // namespace shadowlab::izb
