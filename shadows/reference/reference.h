// The exact shadow reference: visibility of a light from every G-buffer point, by casting
// shadow rays with Embree 3 against the same world-space triangles the rasterizer draws.
// Every technique's V buffer is measured against this one (conventions.md, "Figures and
// errors").
//
//   point, spot:  V in {0, 1}: one ray to the light position.
//   directional:  V in {0, 1}: one ray towards the light, to infinity; a sun with an
//                 angular size (angularDiameterDeg > 0): V = visible fraction of n x n
//                 stratified directions uniform in solid angle over its cap, each a ray
//                 to infinity (shading/light_sampling.h, sunCapDirection).
//   disk, rect:   V = visible fraction of n x n stratified samples on the light
//                 (default 32 x 32 = 1024), an estimate of the fraction of the light's
//                 area seen from P (shading/light_sampling.h).
// A light (or light sample) on or behind the plane of the surface, dot(N, L - P) <= 0,
// is invisible, and so is a sun's direction below the surface's horizon, dot(N, d) <= 0,
// as is a point outside a spot light's cone (the same hard cone as
// shading/lights.h): no ray is cast for them. Pixels with hit = 0 get V = 0.
// Through casters that are not opaque, a ray's 0 or 1 becomes the light it passes: the
// product of what each translucent surface it crosses lets through, times exp(-optical
// depth) of the density volumes (caster_transmission.h, volume_march.h); V is the
// luminance of that product.
//
// Each pixel depends only on its own G-buffer entry and, for area lights and suns with a
// size, on a random stream seeded by (options.seed, pixel index), or on its place in its
// sequence (options.sequence), so V is the same bytes for any number of threads.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/scene.h"
#include "shading/gbuffer.h"
#include "shading/pixel_sequence.h"
#include "shadows/caster_transmission.h"
#include "shadows/progress.h"
#include "shadows/ray_offset.h"

namespace shadowlab {

// How a receiver's shadow rays go to Embree: together as a coherent stream (rtcOccluded1M,
// traced in packets), or one rtcOccluded1 each, the plain twin the stream is held to bit
// for bit (both answer the same occlusion queries in robust mode).
enum class RayQueries { Stream, Single };

struct ReferenceOptions {
    int areaSamplesPerAxis = 32;       // area lights, suns with a size: n x n strata, one sample each
    uint64_t seed = 0x5eed5eed5eedull;  // jitter; pixel k uses PCG32 stream k
    Progress* progress = nullptr;       // counts the rows done; null: reports nothing
    RayQueries queries = RayQueries::Stream;
    // Instead of n x n jittered strata, the samples of an area light or a sun with a size
    // are the pixel's points of a sequence that moves on from frame to frame
    // (shading/pixel_sequence.h): the few noisy rays of a real-time tracer
    // (shadows/raytraced/). A light without a size still has its one ray.
    std::optional<PixelSequence> sequence = std::nullopt;
    // Trace each ray for its first occluder (a closest-hit query, rtcIntersect) instead of
    // asking only whether one exists, and report where it is (Passed::occluderDistance).
    bool occluderDistance = false;
};

class ReferenceVisibility {
public:
    // Builds the Embree scene (robust mode, one triangle geometry). With a transmission
    // whose casters are not all opaque (read in place: it must outlive this), shadow rays
    // pass through translucent surfaces, the holes of cut-outs and the density volumes,
    // taking what each lets through (caster_transmission.h); otherwise every triangle is
    // opaque. No default: a scene's reference must pass its transmission, or its cut-outs
    // would be solid; null is for bare geometry. Throws std::invalid_argument for a vertex
    // index out of range, std::runtime_error if Embree reports an error.
    ReferenceVisibility(const WorldGeometry& world, const CasterTransmission* transmission);
    ~ReferenceVisibility();
    ReferenceVisibility(const ReferenceVisibility&) = delete;
    ReferenceVisibility& operator=(const ReferenceVisibility&) = delete;

    // V per pixel (see the header comment). Throws std::invalid_argument if the G-buffer's
    // arrays are not all width * height long, or options.areaSamplesPerAxis (or the
    // sequence's count) < 1 for an area light or a sun with a size.
    std::vector<float> visibility(const GBuffer& gbuffer, const Light& light,
                                  const ReferenceOptions& options = {}) const;
    // V and, through casters that are not opaque, the light passed per channel (the mean
    // over an area light's samples), V its luminance; `coloured` is empty with opaque ones.
    // With options.occluderDistance, per pixel: the distance (m) from P to the first
    // occluder along each ray that has one, averaged over those rays, and their count (0
    // and 0 where no ray has one, or the pixel is empty). An occluder is the nearest surface
    // that takes light from the ray: a solid one, or a translucent one, which the ray
    // passes with what it lets through (a cut-out's hole is no occluder, nor a density
    // volume, which has no surface); the distance is measured to the surface's plane, in
    // double, from the triangle's vertices, so it does not depend on Embree's SIMD width.
    struct Passed {
        std::vector<float> visibility;
        std::vector<glm::vec3> coloured;
        std::vector<float> occluderDistance;
        std::vector<uint32_t> occludedRays;
        uint64_t raysCast = 0;   // by this call
    };
    Passed passed(const GBuffer& gbuffer, const Light& light, const ReferenceOptions& options = {}) const;

    // The light per channel a distant source in `direction` (unit) passes to the surface
    // point P of geometric normal N: 0 behind N's plane, else what the casters on the ray to
    // infinity from visibility()'s origin let through (1 or 0 with opaque casters). For
    // integrators that choose their own directions (the environment reference); not counted
    // in raysCast().
    glm::vec3 directionPassed(const glm::vec3& P, const glm::vec3& N, const glm::dvec3& direction) const;
    // The same for a point `target` (a sample on an area source): in front of N's plane and
    // nothing in the way of the segment, which stops the ray offset short of the target.
    bool pointVisible(const glm::vec3& P, const glm::vec3& N, const glm::dvec3& target) const;

    // The shadow rays of one receiver, queued and traced together; one per thread, reused,
    // so a steady state allocates nothing.
    class RayBatch {
    public:
        explicit RayBatch(RayQueries queries = RayQueries::Stream);
        ~RayBatch();
        RayBatch(const RayBatch&) = delete;
        RayBatch& operator=(const RayBatch&) = delete;
        struct Samples;   // reference.cpp

    private:
        friend class ReferenceVisibility;
        std::unique_ptr<Samples> samples_;
        RayQueries queries_;
    };
    // directionPassed for each of `directions` from one point, traced together in `batch`:
    // element k is direction k's, the same bits as directionPassed gives; valid until the
    // batch's next use.
    std::span<const glm::vec3> directionsPassed(const glm::vec3& P, const glm::vec3& N,
                                                std::span<const glm::dvec3> directions, RayBatch& batch) const;

    // Shadow rays cast by all visibility() calls so far (for Mrays/s in benchmarks).
    uint64_t raysCast() const { return raysCast_.load(); }

    // Distance (m) the shadow-ray origin is moved from P along N (shadows/ray_offset.h).
    double shadowRayOffset(const glm::vec3& P) const;

private:
    struct Embree;
    std::unique_ptr<Embree> embree_;
    double sceneDiagonal_ = 0.0;  // of the bounding box of all vertices, m
    const CasterTransmission* transmission_;   // null: every caster opaque
    mutable std::atomic<uint64_t> raysCast_{0};
};

}  // namespace shadowlab
