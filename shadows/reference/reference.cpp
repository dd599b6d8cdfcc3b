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

// ---- Embree scene ----------------------------------------------------------------------
struct ReferenceVisibility::Embree {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
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

void attachTriangles(RTCDevice device, RTCScene scene, const WorldGeometry& world, bool filtered) {
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
    if (filtered) rtcSetGeometryOccludedFilterFunction(geometry.get(), transmissionFilter);
    rtcCommitGeometry(geometry.get());
    rtcAttachGeometry(scene, geometry.get());
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

namespace {

struct TransmissionContext {
    RTCIntersectContext base;   // first: Embree's pointer to it is a pointer to this
    const CasterTransmission* transmission;
    std::vector<Crossing>* crossed;
};

// The occlusion filter (rtcSetGeometryOccludedFilterFunction): a hit on a solid point
// stays valid and ends the query; any other is rejected, and a translucent one noted. A
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
struct ReferenceVisibility::RayBatch::Samples {
    std::vector<glm::vec3> lights;       // per sample
    std::vector<RTCRay> rays;            // ray k's id is k
    std::vector<uint32_t> sampleOfRay;
    std::vector<Crossing> crossed;
    AreaLightPoints lightPoints;         // an area light's, or a sun's directions, for the receiver
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

    // Fills in the light of every ray's sample.
    void trace(RTCScene scene, const CasterTransmission* transmission, RayQueries queries) {
        if (rays.empty()) return;
        TransmissionContext context{{}, transmission, &crossed};
        rtcInitIntersectContext(&context.base);
        crossed.clear();
        if (queries == RayQueries::Stream) {
            context.base.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
            rtcOccluded1M(scene, &context.base, rays.data(), unsigned(rays.size()), sizeof(RTCRay));
        } else {
            for (RTCRay& ray : rays) rtcOccluded1(scene, &context.base, &ray);
        }
        count += rays.size();
        if (!transmission) {   // opaque casters: no crossings to share out
            for (uint32_t k = 0; k < rays.size(); ++k) lights[sampleOfRay[k]] = lightOfRay(rays[k], nullptr, {});
            return;
        }
        std::ranges::sort(crossed, crossingOrder);
        auto first = crossed.begin();
        for (uint32_t k = 0; k < rays.size(); ++k) {
            const auto last = std::find_if(first, crossed.end(), [k](const Crossing& c) { return c.ray != k; });
            lights[sampleOfRay[k]] = lightOfRay(rays[k], transmission, {first, last});
            first = last;
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

// Queues n x n stratified samples of an area light. The jitter is drawn for every stratum,
// so sample positions never depend on geometry.
void addAreaSamples(Samples& samples, const Receiver& r, const AreaLightFrame& frame, int n, Pcg32 rng) {
    samples.lightPoints.fill(frame, n, rng);
    const std::vector<glm::dvec3>& targets = samples.lightPoints.points();
    samples.segmentEnds.resize(targets.size());
    for (size_t k = 0; k < targets.size(); ++k) samples.segmentEnds[k] = segmentEnd(r, targets[k]);   // vectorised
    for (size_t k = 0; k < targets.size(); ++k) addPointSample(samples, r, targets[k], samples.segmentEnds[k]);
}

// Queues n x n stratified directions towards a sun with an angular size, in its cap
// (light_sampling.h, sunCapDirection): like an area light's points, drawn for every
// stratum, and a direction below the surface's horizon is dark, as an area light's point
// behind it is.
void addSunSamples(Samples& samples, const Receiver& r, const SunCap& cap, int n, Pcg32 rng) {
    samples.lightPoints.fill(cap, n, rng);
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

void addPixelSamples(Samples& samples, const LightQuery& q, const Receiver& r, uint64_t pixel) {
    switch (q.light.type) {
        case LightType::Point:
            return addPointSample(samples, r, glm::dvec3(q.light.position));
        case LightType::Spot:
            if (!insideSpotCone(q.light, glm::vec3(r.P))) return samples.addKnown(glm::vec3(0.0f));
            return addPointSample(samples, r, glm::dvec3(q.light.position));
        case LightType::Directional:
            if (q.sun) return addSunSamples(samples, r, *q.sun, q.options.areaSamplesPerAxis, Pcg32(q.options.seed, pixel));
            return addDirectionSample(samples, r, glm::dvec3(q.light.direction));
        case LightType::Disk:
        case LightType::Rectangle:
            return addAreaSamples(samples, r, q.frame, q.options.areaSamplesPerAxis, Pcg32(q.options.seed, pixel));
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
        attachTriangles(embree_->device, embree_->scene, world, transmission_ != nullptr);
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
    samples.trace(embree_->scene, transmission_, batch.queries_);
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

ReferenceVisibility::Passed ReferenceVisibility::passed(const GBuffer& gbuffer, const Light& light,
                                                        const ReferenceOptions& options) const {
    requireConsistent(gbuffer, "ReferenceVisibility::visibility");
    const bool area = light.type == LightType::Disk || light.type == LightType::Rectangle;
    const bool sun = light.type == LightType::Directional && light.angularDiameterDeg > 0.0f;
    if ((area || sun) && options.areaSamplesPerAxis < 1) {
        throw std::invalid_argument("ReferenceVisibility: areaSamplesPerAxis must be >= 1");
    }
    const LightQuery query{light, area ? areaLightFrame(light) : AreaLightFrame{},
                           sun ? std::optional(sunCap(light)) : std::nullopt, options};
    Passed out;
    out.visibility.assign(gbuffer.pixelCount(), 0.0f);
    if (transmission_) out.coloured.assign(gbuffer.pixelCount(), glm::vec3(0.0f));
    const ProgressStage progress(options.progress, "reference rays: row", uint64_t(gbuffer.height));
    tbb::parallel_for(tbb::blocked_range<int>(0, gbuffer.height), [&](const tbb::blocked_range<int>& rows) {
        Samples samples;   // a batch's, its buffers reused
        std::vector<QueuedPixel> queued;
        const auto traceQueued = [&] {
            samples.trace(embree_->scene, transmission_, options.queries);
            for (size_t q = 0; q < queued.size(); ++q) {
                const size_t end = q + 1 < queued.size() ? queued[q + 1].firstSample : samples.lights.size();
                const glm::vec3 passed = meanLight(samples, queued[q].firstSample, end);
                // Opaque casters pass the same value in every channel: V is that value.
                out.visibility[queued[q].pixel] = transmission_ ? luminance(passed) : passed.x;
                if (transmission_) out.coloured[queued[q].pixel] = passed;
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
                addPixelSamples(samples, query, receiverAt(gbuffer.position[k], gbuffer.normal[k], sceneDiagonal_), k);
                if (samples.rays.size() >= kBatchRays) traceQueued();
            }
            traceQueued();
            progress.advance();
        }
        raysCast_ += samples.count;  // integer sum: the total is the same in any order
    });
    return out;
}

std::vector<float> ReferenceVisibility::visibility(const GBuffer& gbuffer, const Light& light,
                                                   const ReferenceOptions& options) const {
    return passed(gbuffer, light, options).visibility;
}

}  // namespace shadowlab
