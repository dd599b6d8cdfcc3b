// Exact shadow reference with Embree 3 (see reference.h for what V means per light type).
//
// Embree runs in robust mode (RTC_SCENE_FLAG_ROBUST: conservative BVH traversal and no
// accuracy-reducing shortcuts), so shadow rays do not slip through the seams between the
// triangles of an occluder (Embree's own documentation of the flag). Occlusion
// queries (rtcOccluded1) stop at the first hit found; the answer is a boolean that does not
// depend on which hit that is, so BVH layout and thread count cannot change it.
#include "shadows/reference/reference.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
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
// ShadowRays::passed).
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


// ---- Shadow rays -----------------------------------------------------------------------
// What an occlusion query through casters that are not opaque carries: Embree hands the
// context to the filter, which lets the ray pass every surface that is not solid and notes
// what each translucent one passes.
struct Crossing {
    uint32_t instance, triangle;
    float t;            // along the ray
    glm::vec3 passed;
};

struct TransmissionContext {
    RTCIntersectContext base;   // first: Embree's pointer to it is a pointer to this
    const CasterTransmission* transmission;
    std::vector<Crossing>* crossed;
};

// The occlusion filter (rtcSetGeometryOccludedFilterFunction): a hit on a solid point
// stays valid and ends the query; any other is rejected, and a translucent one noted.
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
        context->crossed->push_back({context->transmission->instanceOf(triangle), triangle, t, passed});
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

// Casts occlusion rays for one task and counts them.
class ShadowRays {
public:
    ShadowRays(RTCScene scene, const CasterTransmission* transmission) : scene_(scene), transmission_(transmission) {}

    // True if nothing blocks origin + t * direction for t in [0, tFar].
    bool unblocked(const glm::vec3& origin, const glm::vec3& direction, float tFar) {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        return reachesEnd(context, origin, direction, tFar);
    }

    // The light that passes along origin + t * direction, t in [0, tFar], per channel: 0 or
    // 1 for opaque casters; through others the product of what each translucent surface
    // passes, and exp(-optical depth) of the volumes. Each surface counts once: a ray
    // through an edge or a corner that triangles of a mesh share hits each of them at the
    // same t, and Embree may report one hit twice, so crossings of one instance closer than
    // kSameCrossing (of t) on triangles that share a vertex are one (two strands of hair, one
    // instance, do not). The product is taken in (instance, t) order, so the bits do not
    // depend on the order the BVH found them in.
    glm::vec3 passed(const glm::vec3& origin, const glm::vec3& direction, float tFar) {
        if (!transmission_) return glm::vec3(unblocked(origin, direction, tFar) ? 1.0f : 0.0f);
        TransmissionContext context{{}, transmission_, &crossed_};
        rtcInitIntersectContext(&context.base);
        crossed_.clear();
        if (!reachesEnd(context.base, origin, direction, tFar)) return glm::vec3(0.0f);
        std::ranges::sort(crossed_, [](const Crossing& a, const Crossing& b) {
            if (a.instance != b.instance) return a.instance < b.instance;
            return a.t != b.t ? a.t < b.t : a.triangle < b.triangle;
        });
        glm::vec3 product(1.0f);
        for (size_t k = 0; k < crossed_.size(); ++k) {
            const Crossing& c = crossed_[k];
            const bool same = k > 0 && c.instance == crossed_[k - 1].instance &&
                              c.t - crossed_[k - 1].t <= kSameCrossing * c.t &&
                              (c.triangle == crossed_[k - 1].triangle ||
                               transmission_->shareVertex(c.triangle, crossed_[k - 1].triangle));
            if (!same) product *= c.passed;
        }
        const std::span<const DensityVolume> volumes = transmission_->volumes();
        if (volumes.empty()) return product;
        const glm::dvec3 a(origin), d(direction);
        const double t = std::isfinite(tFar) ? double(tFar) : beyondVolumes(volumes, a, d);
        return product * float(portable::exp(-opticalDepth(volumes, a, a + t * d)));
    }
    uint64_t count() const { return count_; }

private:
    // Whether the ray reaches tFar: rtcOccluded1 sets tfar to -inf when it finds an occluder
    // (a hit the filter, if any, kept) and leaves it otherwise.
    bool reachesEnd(RTCIntersectContext& context, const glm::vec3& origin, const glm::vec3& direction, float tFar) {
        RTCRay ray{};
        ray.org_x = origin.x, ray.org_y = origin.y, ray.org_z = origin.z;
        ray.dir_x = direction.x, ray.dir_y = direction.y, ray.dir_z = direction.z;
        ray.tnear = 0.0f;
        ray.tfar = tFar;
        ray.mask = ~0u;
        rtcOccluded1(scene_, &context, &ray);
        ++count_;
        return ray.tfar != -std::numeric_limits<float>::infinity();
    }

    RTCScene scene_;
    const CasterTransmission* transmission_;
    std::vector<Crossing> crossed_;
    uint64_t count_ = 0;
};

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

// The light passed from one point of a light: 0 behind the surface, else what the casters
// in between let through.
glm::vec3 pointPassed(ShadowRays& rays, const Receiver& r, const glm::dvec3& target) {
    if (!faces(r, target - r.P)) {
        return glm::vec3(0.0f);
    }
    const glm::dvec3 toTarget = target - glm::dvec3(r.origin);
    // Stop `offset` short of the target (see the offset derivation). A target closer than
    // that leaves no segment for an occluder to sit on.
    const double tFar = 1.0 - r.offset / glm::length(toTarget);
    return tFar <= 0.0 ? glm::vec3(1.0f) : rays.passed(r.origin, glm::vec3(toTarget), float(tFar));
}

glm::vec3 directionPassed(ShadowRays& rays, const Receiver& r, const glm::dvec3& towardsLight) {
    if (!faces(r, towardsLight)) return glm::vec3(0.0f);
    return rays.passed(r.origin, glm::vec3(towardsLight), std::numeric_limits<float>::infinity());
}

// The mean passed over n x n stratified samples of the light: with opaque casters the
// visible fraction, count / n^2, exact in float.
glm::vec3 areaPassed(ShadowRays& rays, const Receiver& r, const AreaLightFrame& frame, int n, Pcg32 rng) {
    glm::vec3 sum(0.0f);
    for (int b = 0; b < n; ++b) {
        for (int a = 0; a < n; ++a) {
            // Draw the jitter for every stratum, so sample positions never depend on geometry.
            const glm::dvec3 target = areaLightPoint(frame, jitteredSample(a, b, n, rng));
            sum += pointPassed(rays, r, target);
        }
    }
    return sum / float(n * n);
}

// Everything about the light that is the same for every pixel.
struct LightQuery {
    const Light& light;
    AreaLightFrame frame;
    ReferenceOptions options;
};

glm::vec3 pixelPassed(ShadowRays& rays, const LightQuery& q, const Receiver& r, uint64_t pixel) {
    switch (q.light.type) {
        case LightType::Point:
            return pointPassed(rays, r, glm::dvec3(q.light.position));
        case LightType::Spot:
            return insideSpotCone(q.light, glm::vec3(r.P)) ? pointPassed(rays, r, glm::dvec3(q.light.position))
                                                           : glm::vec3(0.0f);
        case LightType::Directional:
            return directionPassed(rays, r, glm::dvec3(q.light.direction));
        case LightType::Disk:
        case LightType::Rectangle:
            return areaPassed(rays, r, q.frame, q.options.areaSamplesPerAxis, Pcg32(q.options.seed, pixel));
    }
    return glm::vec3(0.0f);
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
    ShadowRays rays(embree_->scene, transmission_);
    return shadowlab::directionPassed(rays, receiverAt(P, N, sceneDiagonal_), direction);
}

bool ReferenceVisibility::pointVisible(const glm::vec3& P, const glm::vec3& N, const glm::dvec3& target) const {
    ShadowRays rays(embree_->scene, transmission_);
    return glm::any(glm::greaterThan(pointPassed(rays, receiverAt(P, N, sceneDiagonal_), target), glm::vec3(0.0f)));
}

ReferenceVisibility::Passed ReferenceVisibility::passed(const GBuffer& gbuffer, const Light& light,
                                                        const ReferenceOptions& options) const {
    requireConsistent(gbuffer, "ReferenceVisibility::visibility");
    const bool area = light.type == LightType::Disk || light.type == LightType::Rectangle;
    if (area && options.areaSamplesPerAxis < 1) {
        throw std::invalid_argument("ReferenceVisibility: areaSamplesPerAxis must be >= 1");
    }
    const LightQuery query{light, area ? areaLightFrame(light) : AreaLightFrame{}, options};
    Passed out;
    out.visibility.assign(gbuffer.pixelCount(), 0.0f);
    if (transmission_) out.coloured.assign(gbuffer.pixelCount(), glm::vec3(0.0f));
    const ProgressStage progress(options.progress, "reference rays: row", uint64_t(gbuffer.height));
    tbb::parallel_for(tbb::blocked_range<int>(0, gbuffer.height), [&](const tbb::blocked_range<int>& rows) {
        ShadowRays rays(embree_->scene, transmission_);
        for (int j = rows.begin(); j != rows.end(); ++j) {
            for (int i = 0; i < gbuffer.width; ++i) {
                const size_t k = gbuffer.index(i, j);
                if (!gbuffer.hit[k]) {
                    continue;
                }
                const glm::vec3 passed =
                    pixelPassed(rays, query, receiverAt(gbuffer.position[k], gbuffer.normal[k], sceneDiagonal_), k);
                // Opaque casters pass the same value in every channel: V is that value.
                out.visibility[k] = transmission_ ? luminance(passed) : passed.x;
                if (transmission_) out.coloured[k] = passed;
            }
            progress.advance();
        }
        raysCast_ += rays.count();  // integer sum: the total is the same in any order
    });
    return out;
}

std::vector<float> ReferenceVisibility::visibility(const GBuffer& gbuffer, const Light& light,
                                                   const ReferenceOptions& options) const {
    return passed(gbuffer, light, options).visibility;
}

}  // namespace shadowlab
