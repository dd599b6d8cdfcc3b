// Exact shadow reference with Embree 3 (see reference.h for what V means per light type).
//
// Embree runs in robust mode (RTC_SCENE_FLAG_ROBUST: conservative BVH traversal and no
// accuracy-reducing shortcuts), so shadow rays do not slip through the seams between the
// triangles of an occluder (Embree's own documentation of the flag). Occlusion
// queries stop at the first hit found; the answer is a boolean that does not depend on
// which hit that is, so BVH layout and thread count cannot change it, nor whether a ray is
// traced alone (rtcOccluded1) or with the other rays of its pixel in packets
// (rtcOccluded1M, a coherent stream): see RayBatch::Samples.
#include "shadows/reference/reference.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <embree3/rtcore.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "shading/gbuffer_build.h"
#include "shading/light_sampling.h"
#include "shading/lights.h"
#include "shading/luminance.h"
#include "shadows/volume_march.h"

namespace shadowlab {

double ReferenceVisibility::shadowRayOffset(const glm::vec3& P) const {
    return shadowlab::shadowRayOffset(P, sceneDiagonal_);
}

// The casters' triangles as Embree keeps them (its buffers, alive with the scene): where a
// closest-hit query reports a triangle, the distance to its plane is computed from these.
namespace reference_rays {
struct Triangles {
    const glm::vec3* vertices = nullptr;
    const glm::uvec3* indices = nullptr;
};
}  // namespace reference_rays

// ---- Embree scene ----------------------------------------------------------------------
struct ReferenceVisibility::Embree {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    reference_rays::Triangles triangles;   // Embree's copy, read where a closest hit lands
    ~Embree() {
        if (scene) rtcReleaseScene(scene);
        if (device) rtcReleaseDevice(device);
    }
};

namespace {

void transmissionFilter(const RTCFilterFunctionNArguments* args);

void throwIfEmbreeError(RTCDevice device, const char* what) {
    const RTCError error = rtcGetDeviceError(device);
    if (error != RTC_ERROR_NONE) {
        throw std::runtime_error(std::string("Embree: ") + what + " failed with RTCError " +
                                 std::to_string(int(error)));
    }
}

// ThreadSanitizer sees oneTBB's hand-offs only in code built for it, and Debian's Embree is
// not: the tasks of its BVH build, run by TBB's workers, would be reported as races on
// Embree's task contexts. A TSan build (scripts/tsan.sh) therefore builds the BVH in an arena
// of one thread, where no worker touches Embree's tasks; every loop of ours stays parallel and
// checked. The BVH's layout cannot change an answer (see the top of this file and
// passedAlong).
#if defined(__SANITIZE_THREAD__)
#define SHADOWLAB_THREAD_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define SHADOWLAB_THREAD_SANITIZER 1
#endif
#endif

void commitScene(RTCScene scene) {
#ifdef SHADOWLAB_THREAD_SANITIZER
    tbb::task_arena(1).execute([scene] { rtcCommitScene(scene); });
#else
    rtcCommitScene(scene);
#endif
}

reference_rays::Triangles attachTriangles(RTCDevice device, RTCScene scene, const WorldGeometry& world, bool filtered) {
    static_assert(sizeof(glm::vec3) == 3 * sizeof(float) && sizeof(glm::uvec3) == 3 * sizeof(unsigned));
    // Released on every path, including the throw below.
    const std::unique_ptr<RTCGeometryTy, decltype(&rtcReleaseGeometry)> geometry(
        rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE), rtcReleaseGeometry);
    // Embree allocates these buffers itself, with the padding its SIMD loads need.
    void* vertices = rtcSetNewGeometryBuffer(geometry.get(), RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                             sizeof(glm::vec3), world.positions.size());
    void* indices = rtcSetNewGeometryBuffer(geometry.get(), RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                            sizeof(glm::uvec3), world.triangles.size());
    throwIfEmbreeError(device, "allocating the triangle buffers");
    std::memcpy(vertices, world.positions.data(), world.positions.size() * sizeof(glm::vec3));
    std::memcpy(indices, world.triangles.data(), world.triangles.size() * sizeof(glm::uvec3));
    if (filtered) {   // the same filter for occlusion and closest-hit queries
        rtcSetGeometryOccludedFilterFunction(geometry.get(), transmissionFilter);
        rtcSetGeometryIntersectFilterFunction(geometry.get(), transmissionFilter);
    }
    rtcCommitGeometry(geometry.get());
    rtcAttachGeometry(scene, geometry.get());
    return {static_cast<const glm::vec3*>(vertices), static_cast<const glm::uvec3*>(indices)};
}


}  // namespace

// ---- Shadow rays -----------------------------------------------------------------------
// What an occlusion query through casters that are not opaque carries: Embree hands the
// context to the filter, which lets the ray pass every surface that is not solid and notes
// what each translucent one passes, under the ray's id (its index in the batch). A named
// namespace: RayBatch::Samples, a class of the header's, keeps a list of them.
namespace reference_rays {
struct Crossing {
    uint32_t ray, instance, triangle;
    float t;            // along the ray
    glm::vec3 passed;
};
}  // namespace reference_rays
using reference_rays::Crossing;
using reference_rays::Triangles;

namespace {

struct TransmissionContext {
    RTCIntersectContext base;   // first: Embree's pointer to it is a pointer to this
    const CasterTransmission* transmission;
    std::vector<Crossing>* crossed;
};

// The filter of occlusion and closest-hit queries: a hit on a solid point stays valid (it
// ends an occlusion query, and is a candidate for the closest hit); any other is
// rejected, and a translucent one noted. A
// stream may hand it packets of any size and order (Embree's rtcOccluded1M), so each lane
// names its ray by id.
void transmissionFilter(const RTCFilterFunctionNArguments* args) {
    const auto* context = reinterpret_cast<const TransmissionContext*>(args->context);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        const uint32_t triangle = RTCHitN_primID(args->hit, args->N, i);
        const float u = RTCHitN_u(args->hit, args->N, i), v = RTCHitN_v(args->hit, args->N, i);
        const glm::vec3 passed = context->transmission->passedAt(triangle, u, v);
        if (passed == glm::vec3(0.0f)) continue;
        args->valid[i] = 0;
        if (passed == glm::vec3(1.0f)) continue;   // a cut-out's hole
        const float t = RTCRayN_tfar(args->ray, args->N, i);   // the hit's distance, during the filter
        const uint32_t ray = RTCRayN_id(args->ray, args->N, i);
        context->crossed->push_back({ray, context->transmission->instanceOf(triangle), triangle, t, passed});
    }
}

// The largest t at which origin + t direction can still be inside a volume's box.
double beyondVolumes(std::span<const DensityVolume> volumes, const glm::dvec3& origin, const glm::dvec3& direction) {
    double reach = 0.0;
    for (const DensityVolume& v : volumes) {
        for (int corner = 0; corner < 8; ++corner) {
            const glm::dvec3 p(corner & 1 ? v.max.x : v.min.x, corner & 2 ? v.max.y : v.min.y,
                               corner & 4 ? v.max.z : v.min.z);
            reach = std::max(reach, glm::length(p - origin));
        }
    }
    return 2.0 * reach / glm::length(direction);
}

// Crossings of one surface closer than this, relative to t, are one (a shared edge).
constexpr float kSameCrossing = 1e-5f;

// The light that passes along a ray that reached its end, per channel: through casters
// that are not opaque the product of what each translucent surface it crossed passes, and
// exp(-optical depth) of the volumes. Each surface counts once: a ray through an edge or a
// corner that triangles of a mesh share hits each of them at the same t, and Embree may
// report one hit twice, so crossings of one instance closer than kSameCrossing (of t) on
// triangles that share a vertex are one (two strands of hair, one instance, do not).
// `crossed` is sorted in (instance, t, triangle) order, so the bits do not depend on the
// order the BVH found them in.
glm::vec3 passedAlong(const CasterTransmission& transmission, const RTCRay& ray, std::span<const Crossing> crossed) {
    glm::vec3 product(1.0f);
    for (size_t k = 0; k < crossed.size(); ++k) {
        const Crossing& c = crossed[k];
        const bool same = k > 0 && c.instance == crossed[k - 1].instance &&
                          c.t - crossed[k - 1].t <= kSameCrossing * c.t &&
                          (c.triangle == crossed[k - 1].triangle || transmission.shareVertex(c.triangle, crossed[k - 1].triangle));
        if (!same) product *= c.passed;
    }
    const std::span<const DensityVolume> volumes = transmission.volumes();
    if (volumes.empty()) return product;
    // The ray reached its end: rtcOccluded left tfar as it was.
    const glm::dvec3 a(glm::vec3(ray.org_x, ray.org_y, ray.org_z)), d(glm::vec3(ray.dir_x, ray.dir_y, ray.dir_z));
    const double t = std::isfinite(ray.tfar) ? double(ray.tfar) : beyondVolumes(volumes, a, d);
    return product * float(portable::exp(-opticalDepth(volumes, a, a + t * d)));
}

// A shadow ray from origin along direction for t in [0, tFar], named `id` for the filter.
RTCRay shadowRay(const glm::vec3& origin, const glm::vec3& direction, float tFar, uint32_t id) {
    RTCRay ray{};
    ray.org_x = origin.x, ray.org_y = origin.y, ray.org_z = origin.z;
    ray.dir_x = direction.x, ray.dir_y = direction.y, ray.dir_z = direction.z;
    ray.tnear = 0.0f;
    ray.tfar = tFar;
    ray.mask = ~0u;
    ray.id = id;
    return ray;
}

// The light a traced ray brings: 0 if something solid stopped it (rtcOccluded set its tfar
// to -inf: a hit the filter, if any, kept); else 1 through opaque casters, or what its
// crossings, sorted by crossingOrder, let through.
glm::vec3 lightOfRay(const RTCRay& ray, const CasterTransmission* transmission, std::span<const Crossing> crossed) {
    if (ray.tfar == -std::numeric_limits<float>::infinity()) return glm::vec3(0.0f);
    return transmission ? passedAlong(*transmission, ray, crossed) : glm::vec3(1.0f);
}

// By ray, then in passedAlong's (instance, t, triangle) order.
bool crossingOrder(const Crossing& a, const Crossing& b) {
    if (a.ray != b.ray) return a.ray < b.ray;
    if (a.instance != b.instance) return a.instance < b.instance;
    return a.t != b.t ? a.t < b.t : a.triangle < b.triangle;
}

// The t (a fraction of the ray's direction) where the ray meets the plane of `triangle`,
// in double from its vertices, so that a distance does not depend on how Embree's
// intersector rounded at its SIMD width; Embree's own t for a ray in the plane.
double planeT(const Triangles& triangles, const RTCRay& ray, uint32_t triangle, float embreeT) {
    const glm::uvec3 v = triangles.indices[triangle];
    const glm::dvec3 a(triangles.vertices[v.x]), b(triangles.vertices[v.y]), c(triangles.vertices[v.z]);
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const glm::dvec3 origin(ray.org_x, ray.org_y, ray.org_z), direction(ray.dir_x, ray.dir_y, ray.dir_z);
    const double along = glm::dot(direction, n);
    return along != 0.0 ? glm::dot(a - origin, n) / along : double(embreeT);
}

// Where a closest-hit query's ray meets its first occluder: the nearer of its solid hit and
// its nearest translucent crossing (a cut-out's hole is never noted); NaN for none.
glm::dvec3 firstOccluder(const Triangles& triangles, const RTCRayHit& traced, std::span<const Crossing> crossed) {
    double nearest = std::numeric_limits<double>::infinity();
    if (traced.hit.geomID != RTC_INVALID_GEOMETRY_ID) {
        nearest = planeT(triangles, traced.ray, traced.hit.primID, traced.ray.tfar);
    }
    for (const Crossing& c : crossed) nearest = std::min(nearest, planeT(triangles, traced.ray, c.triangle, c.t));
    if (std::isinf(nearest)) return glm::dvec3(std::numeric_limits<double>::quiet_NaN());
    const glm::dvec3 origin(traced.ray.org_x, traced.ray.org_y, traced.ray.org_z);
    return origin + nearest * glm::dvec3(traced.ray.dir_x, traced.ray.dir_y, traced.ray.dir_z);
}

// One ray traced alone (rtcOccluded1), with nothing allocated unless it crosses a
// translucent surface: for callers that ask about one point at a time.
glm::vec3 tracedAlone(RTCScene scene, const CasterTransmission* transmission, RTCRay ray) {
    std::vector<Crossing> crossed;
    TransmissionContext context{{}, transmission, &crossed};
    rtcInitIntersectContext(&context.base);
    rtcOccluded1(scene, &context.base, &ray);
    std::ranges::sort(crossed, crossingOrder);
    return lightOfRay(ray, transmission, crossed);
}

// The light of a point sample known without a ray: 0 behind the surface (tFar NaN); 1 for
// a target closer than the offset (tFar <= 0), which leaves no segment for an occluder to
// sit on.
std::optional<glm::vec3> knownLight(double tFar) {
    if (std::isnan(tFar)) return glm::vec3(0.0f);
    if (tFar <= 0.0) return glm::vec3(1.0f);
    return std::nullopt;
}

}  // namespace

// The samples of a batch of receivers, in order: each one's light is known without a ray (behind
// the surface, no segment left to block) or is what its shadow ray finds, 0 or 1 through
// opaque casters (passedAlong through others). The rays are queued and traced together:
// a coherent stream (rtcOccluded1M, which Embree cuts into packets of its widest ISA), or,
// the plain twin, one rtcOccluded1 each. Both run the same robust traversal and the same
// filter, and an occlusion query's answer does not depend on which hit ends it, so they
// give the same bytes (tests/shadows/reference/test_reference_packets.cpp holds them to it).
// Traced for their first occluders instead, the rays are closest-hit queries
// (rtcIntersect1M or rtcIntersect1): the same light, since a solid hit found anywhere on
// the segment darkens it either way and the filter notes the same crossings where there
// is none, and where each first occluder is (firstOccluder).
struct ReferenceVisibility::RayBatch::Samples {
    std::vector<glm::vec3> lights;       // per sample
    std::vector<glm::dvec3> occluders;   // per sample, traced for them: where its first occluder is, NaN for none
    std::vector<RTCRay> rays;            // ray k's id is k
    std::vector<RTCRayHit> traced;       // closest-hit queries' rays and hits
    std::vector<uint32_t> sampleOfRay;
    std::vector<Crossing> crossed;
    AreaLightPoints lightPoints;         // an area light's, or a sun's directions, for the receiver
    std::vector<glm::dvec2> sequence;    // a pixel's samples of its sequence (pixel_sequence.h)
    std::vector<double> segmentEnds;     // per light point
    uint64_t count = 0;                  // rays traced

    void clear() {
        lights.clear(), rays.clear(), sampleOfRay.clear();
    }
    void addKnown(const glm::vec3& light) { lights.push_back(light); }
    void addRay(const glm::vec3& origin, const glm::vec3& direction, float tFar) {
        rays.push_back(shadowRay(origin, direction, tFar, uint32_t(rays.size())));
        sampleOfRay.push_back(uint32_t(lights.size()));
        lights.push_back(glm::vec3(0.0f));
    }

    // Fills in the light of every ray's sample; with `closest`, the casters' triangles, the
    // rays are closest-hit queries and each sample's first occluder is filled in too.
    void trace(RTCScene scene, const CasterTransmission* transmission, RayQueries queries, const Triangles* closest) {
        if (closest) occluders.assign(lights.size(), glm::dvec3(std::numeric_limits<double>::quiet_NaN()));
        if (rays.empty()) return;
        TransmissionContext context{{}, transmission, &crossed};
        rtcInitIntersectContext(&context.base);
        if (queries == RayQueries::Stream) context.base.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
        crossed.clear();
        if (closest) {
            intersect(scene, context.base, queries);
        } else if (queries == RayQueries::Stream) {
            rtcOccluded1M(scene, &context.base, rays.data(), unsigned(rays.size()), sizeof(RTCRay));
        } else {
            for (RTCRay& ray : rays) rtcOccluded1(scene, &context.base, &ray);
        }
        count += rays.size();
        if (!transmission && !closest) {   // opaque casters: no crossings to share out
            for (uint32_t k = 0; k < rays.size(); ++k) lights[sampleOfRay[k]] = lightOfRay(rays[k], nullptr, {});
            return;
        }
        if (transmission) std::ranges::sort(crossed, crossingOrder);   // opaque casters: none
        auto first = crossed.begin();
        for (uint32_t k = 0; k < rays.size(); ++k) {
            const auto last = std::find_if(first, crossed.end(), [k](const Crossing& c) { return c.ray != k; });
            lights[sampleOfRay[k]] = lightOfRay(rays[k], transmission, {first, last});
            if (closest) occluders[sampleOfRay[k]] = firstOccluder(*closest, traced[k], {first, last});
            first = last;
        }
    }

private:
    // The rays as closest-hit queries; a ray that hit something solid is then marked as
    // rtcOccluded marks it (tfar -inf), for lightOfRay.
    void intersect(RTCScene scene, RTCIntersectContext& context, RayQueries queries) {
        traced.resize(rays.size());
        for (size_t k = 0; k < rays.size(); ++k) {
            traced[k].ray = rays[k];
            traced[k].hit.geomID = RTC_INVALID_GEOMETRY_ID;
            traced[k].hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        }
        if (queries == RayQueries::Stream) {
            rtcIntersect1M(scene, &context, traced.data(), unsigned(traced.size()), sizeof(RTCRayHit));
        } else {
            for (RTCRayHit& t : traced) rtcIntersect1(scene, &context, &t);
        }
        for (size_t k = 0; k < rays.size(); ++k) {
            if (traced[k].hit.geomID != RTC_INVALID_GEOMETRY_ID) rays[k].tfar = -std::numeric_limits<float>::infinity();
        }
    }
};

ReferenceVisibility::RayBatch::RayBatch(RayQueries queries) : samples_(std::make_unique<Samples>()), queries_(queries) {}
ReferenceVisibility::RayBatch::~RayBatch() = default;

namespace {

using Samples = ReferenceVisibility::RayBatch::Samples;

// A receiving point and where its shadow rays start.
struct Receiver {
    glm::dvec3 P, N;
    glm::vec3 origin;  // P moved by `offset` along N, rounded once to float
    double offset;
};

// The receiver of a G-buffer point, its rays' origin moved along N (shadows/ray_offset.h).
Receiver receiverAt(const glm::vec3& P, const glm::vec3& N, double sceneDiagonal) {
    const double offset = shadowRayOffset(P, sceneDiagonal);
    return {glm::dvec3(P), glm::dvec3(N), glm::vec3(glm::dvec3(P) + offset * glm::dvec3(N)), offset};
}

bool faces(const Receiver& r, const glm::dvec3& direction) { return glm::dot(r.N, direction) > 0.0; }

// Where the shadow segment from the receiver to a point of a light ends, as a fraction of
// target - origin: `offset` short of the target (see the offset derivation); NaN for a
// target behind the surface, where no ray goes. Both arms computed and one selected, so a
// loop over many targets vectorises.
double segmentEnd(const Receiver& r, const glm::dvec3& target) {
    const double tFar = 1.0 - r.offset / glm::length(target - glm::dvec3(r.origin));
    return faces(r, target - r.P) ? tFar : std::numeric_limits<double>::quiet_NaN();
}

// Queues the sample of one point of a light whose segment ends at tFar: its known light
// (knownLight), else a ray.
void addPointSample(Samples& samples, const Receiver& r, const glm::dvec3& target, double tFar) {
    if (const std::optional<glm::vec3> known = knownLight(tFar)) return samples.addKnown(*known);
    samples.addRay(r.origin, glm::vec3(target - glm::dvec3(r.origin)), float(tFar));
}

void addPointSample(Samples& samples, const Receiver& r, const glm::dvec3& target) {
    addPointSample(samples, r, target, segmentEnd(r, target));
}

void addDirectionSample(Samples& samples, const Receiver& r, const glm::dvec3& towardsLight) {
    if (!faces(r, towardsLight)) return samples.addKnown(glm::vec3(0.0f));
    samples.addRay(r.origin, glm::vec3(towardsLight), std::numeric_limits<float>::infinity());
}

// A pixel of the image: its column, row and index.
struct PixelAt {
    int x, y;
    uint64_t index;
};

// Fills samples.lightPoints with the points of an area light (or a sun's directions, for a
// SunCap) a pixel samples: n x n jittered strata from its own PCG32 stream, or its
// sequence's points for the frame. Drawn for every stratum or sample, so sample positions
// never depend on geometry.
template <class Shape>
void fillLightPoints(Samples& samples, const Shape& shape, const ReferenceOptions& options, const PixelAt& at) {
    if (options.sequence) {
        pixelSamples(*options.sequence, at.x, at.y, at.index, samples.sequence);
        return samples.lightPoints.fill(shape, samples.sequence);
    }
    Pcg32 rng(options.seed, at.index);
    samples.lightPoints.fill(shape, options.areaSamplesPerAxis, rng);
}

// Queues the samples of an area light at samples.lightPoints.
void addAreaSamples(Samples& samples, const Receiver& r) {
    const std::vector<glm::dvec3>& targets = samples.lightPoints.points();
    samples.segmentEnds.resize(targets.size());
    for (size_t k = 0; k < targets.size(); ++k) samples.segmentEnds[k] = segmentEnd(r, targets[k]);   // vectorised
    for (size_t k = 0; k < targets.size(); ++k) addPointSample(samples, r, targets[k], samples.segmentEnds[k]);
}

// Queues the directions towards a sun with an angular size at samples.lightPoints, in its
// cap (light_sampling.h, sunCapDirection): a direction below the surface's horizon is
// dark, as an area light's point behind it is.
void addSunSamples(Samples& samples, const Receiver& r) {
    for (const glm::dvec3& direction : samples.lightPoints.points()) addDirectionSample(samples, r, direction);
}

// The mean light of the traced samples [first, end), summed in their order: with opaque
// casters the visible fraction, count / n^2, exact in float; one sample's own light.
glm::vec3 meanLight(const Samples& samples, size_t first, size_t end) {
    glm::vec3 sum(0.0f);
    for (size_t s = first; s < end; ++s) sum += samples.lights[s];
    return sum / float(end - first);
}

// Pixels whose samples are queued, each from its first sample to the next one's.
struct QueuedPixel {
    size_t pixel, firstSample;
};

// Rays go to Embree in batches of at least this many (or a row's): an area light's pixel
// fills one, a point light's row of pixels shares one, so hard shadows trace in packets too.
constexpr size_t kBatchRays = 256;

// Everything about the light that is the same for every pixel.
struct LightQuery {
    const Light& light;
    AreaLightFrame frame;
    std::optional<SunCap> sun;   // a directional light with an angular size
    ReferenceOptions options;
};

void addPixelSamples(Samples& samples, const LightQuery& q, const Receiver& r, const PixelAt& at) {
    switch (q.light.type) {
        case LightType::Point:
            return addPointSample(samples, r, glm::dvec3(q.light.position));
        case LightType::Spot:
            if (!insideSpotCone(q.light, glm::vec3(r.P))) return samples.addKnown(glm::vec3(0.0f));
            return addPointSample(samples, r, glm::dvec3(q.light.position));
        case LightType::Directional:
            if (!q.sun) return addDirectionSample(samples, r, glm::dvec3(q.light.direction));
            fillLightPoints(samples, *q.sun, q.options, at);
            return addSunSamples(samples, r);
        case LightType::Disk:
        case LightType::Rectangle:
            fillLightPoints(samples, q.frame, q.options, at);
            return addAreaSamples(samples, r);
    }
}

}  // namespace

ReferenceVisibility::ReferenceVisibility(const WorldGeometry& world, const CasterTransmission* transmission)
    : embree_(std::make_unique<Embree>()), sceneDiagonal_(sceneDiagonal(world)),
      transmission_(transmission && transmission->anyNonOpaque() ? transmission : nullptr) {
    for (const glm::uvec3& t : world.triangles) {
        if (std::max({t.x, t.y, t.z}) >= world.positions.size()) {
            throw std::invalid_argument("ReferenceVisibility: vertex index out of range");
        }
    }
    embree_->device = rtcNewDevice(nullptr);
    if (!embree_->device) {
        throwIfEmbreeError(nullptr, "rtcNewDevice");
    }
    embree_->scene = rtcNewScene(embree_->device);
    rtcSetSceneFlags(embree_->scene, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(embree_->scene, RTC_BUILD_QUALITY_HIGH);
    if (!world.triangles.empty()) {
        embree_->triangles = attachTriangles(embree_->device, embree_->scene, world, transmission_ != nullptr);
    }
    commitScene(embree_->scene);
    throwIfEmbreeError(embree_->device, "building the scene");
}

ReferenceVisibility::~ReferenceVisibility() = default;

glm::vec3 ReferenceVisibility::directionPassed(const glm::vec3& P, const glm::vec3& N, const glm::dvec3& direction) const {
    const Receiver r = receiverAt(P, N, sceneDiagonal_);
    if (!faces(r, direction)) return glm::vec3(0.0f);
    return tracedAlone(embree_->scene, transmission_,
                       shadowRay(r.origin, glm::vec3(direction), std::numeric_limits<float>::infinity(), 0));
}

std::span<const glm::vec3> ReferenceVisibility::directionsPassed(const glm::vec3& P, const glm::vec3& N,
                                                                 std::span<const glm::dvec3> directions,
                                                                 RayBatch& batch) const {
    Samples& samples = *batch.samples_;
    samples.clear();
    const Receiver r = receiverAt(P, N, sceneDiagonal_);
    for (const glm::dvec3& direction : directions) addDirectionSample(samples, r, direction);
    samples.trace(embree_->scene, transmission_, batch.queries_, nullptr);
    return samples.lights;
}

bool ReferenceVisibility::pointVisible(const glm::vec3& P, const glm::vec3& N, const glm::dvec3& target) const {
    const Receiver r = receiverAt(P, N, sceneDiagonal_);
    const double tFar = segmentEnd(r, target);
    const std::optional<glm::vec3> known = knownLight(tFar);
    const glm::vec3 light = known ? *known
                                  : tracedAlone(embree_->scene, transmission_,
                                                shadowRay(r.origin, glm::vec3(target - glm::dvec3(r.origin)), float(tFar), 0));
    return glm::any(glm::greaterThan(light, glm::vec3(0.0f)));
}

namespace {

// The mean distance from P to the first occluders of the samples [first, end) that have
// one, summed in their order, and how many have one.
struct OccluderMean {
    float distance = 0.0f;
    uint32_t rays = 0;
};
OccluderMean occluderMean(const Samples& samples, size_t first, size_t end, const glm::vec3& P) {
    double sum = 0.0;
    uint32_t rays = 0;
    for (size_t s = first; s < end; ++s) {
        if (std::isnan(samples.occluders[s].x)) continue;
        sum += glm::length(samples.occluders[s] - glm::dvec3(P)), ++rays;
    }
    return {rays ? float(sum / double(rays)) : 0.0f, rays};
}

void requireSamples(const Light& light, const ReferenceOptions& options) {
    const bool sized = light.type == LightType::Disk || light.type == LightType::Rectangle ||
                       (light.type == LightType::Directional && light.angularDiameterDeg > 0.0f);
    if (sized && options.sequence && options.sequence->count < 1) {
        throw std::invalid_argument("ReferenceVisibility: a pixel sequence's count must be >= 1");
    }
    if (sized && !options.sequence && options.areaSamplesPerAxis < 1) {
        throw std::invalid_argument("ReferenceVisibility: areaSamplesPerAxis must be >= 1");
    }
}

}  // namespace

ReferenceVisibility::Passed ReferenceVisibility::passed(const GBuffer& gbuffer, const Light& light,
                                                        const ReferenceOptions& options) const {
    requireConsistent(gbuffer, "ReferenceVisibility::visibility");
    requireSamples(light, options);
    const bool area = light.type == LightType::Disk || light.type == LightType::Rectangle;
    const bool sun = light.type == LightType::Directional && light.angularDiameterDeg > 0.0f;
    const LightQuery query{light, area ? areaLightFrame(light) : AreaLightFrame{},
                           sun ? std::optional(sunCap(light)) : std::nullopt, options};
    const Triangles* closest = options.occluderDistance ? &embree_->triangles : nullptr;
    Passed out;
    out.visibility.assign(gbuffer.pixelCount(), 0.0f);
    if (transmission_) out.coloured.assign(gbuffer.pixelCount(), glm::vec3(0.0f));
    if (closest) out.occluderDistance.assign(gbuffer.pixelCount(), 0.0f), out.occludedRays.assign(gbuffer.pixelCount(), 0);
    std::atomic<uint64_t> cast{0};
    const ProgressStage progress(options.progress, "reference rays: row", uint64_t(gbuffer.height));
    tbb::parallel_for(tbb::blocked_range<int>(0, gbuffer.height), [&](const tbb::blocked_range<int>& rows) {
        Samples samples;   // a batch's, its buffers reused
        std::vector<QueuedPixel> queued;
        const auto traceQueued = [&] {
            samples.trace(embree_->scene, transmission_, options.queries, closest);
            for (size_t q = 0; q < queued.size(); ++q) {
                const size_t pixel = queued[q].pixel, first = queued[q].firstSample;
                const size_t end = q + 1 < queued.size() ? queued[q + 1].firstSample : samples.lights.size();
                const glm::vec3 passed = meanLight(samples, first, end);
                // Opaque casters pass the same value in every channel: V is that value.
                out.visibility[pixel] = transmission_ ? luminance(passed) : passed.x;
                if (transmission_) out.coloured[pixel] = passed;
                if (!closest) continue;
                const OccluderMean occluders = occluderMean(samples, first, end, gbuffer.position[pixel]);
                out.occluderDistance[pixel] = occluders.distance, out.occludedRays[pixel] = occluders.rays;
            }
            samples.clear(), queued.clear();
        };
        for (int j = rows.begin(); j != rows.end(); ++j) {
            for (int i = 0; i < gbuffer.width; ++i) {
                const size_t k = gbuffer.index(i, j);
                if (!gbuffer.hit[k]) {
                    continue;
                }
                queued.push_back({k, samples.lights.size()});
                addPixelSamples(samples, query, receiverAt(gbuffer.position[k], gbuffer.normal[k], sceneDiagonal_),
                                {i, j, k});
                if (samples.rays.size() >= kBatchRays) traceQueued();
            }
            traceQueued();
            progress.advance();
        }
        raysCast_ += samples.count;  // integer sums: the totals are the same in any order
        cast += samples.count;
    });
    out.raysCast = cast.load();
    return out;
}

std::vector<float> ReferenceVisibility::visibility(const GBuffer& gbuffer, const Light& light,
                                                   const ReferenceOptions& options) const {
    return passed(gbuffer, light, options).visibility;
}

}  // namespace shadowlab
