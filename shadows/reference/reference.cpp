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

#include <embree3/rtcore.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "shading/gbuffer_build.h"
#include "shading/light_sampling.h"
#include "shading/lights.h"

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

void throwIfEmbreeError(RTCDevice device, const char* what) {
    const RTCError error = rtcGetDeviceError(device);
    if (error != RTC_ERROR_NONE) {
        throw std::runtime_error(std::string("Embree: ") + what + " failed with RTCError " +
                                 std::to_string(int(error)));
    }
}

void attachTriangles(RTCDevice device, RTCScene scene, const WorldGeometry& world) {
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
    rtcCommitGeometry(geometry.get());
    rtcAttachGeometry(scene, geometry.get());
}


// ---- Shadow rays -----------------------------------------------------------------------
// Casts occlusion rays for one task and counts them.
class ShadowRays {
public:
    explicit ShadowRays(RTCScene scene) : scene_(scene) {}

    // True if nothing blocks origin + t * direction for t in [0, tFar].
    bool unblocked(const glm::vec3& origin, const glm::vec3& direction, float tFar) {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRay ray{};
        ray.org_x = origin.x, ray.org_y = origin.y, ray.org_z = origin.z;
        ray.dir_x = direction.x, ray.dir_y = direction.y, ray.dir_z = direction.z;
        ray.tnear = 0.0f;
        ray.tfar = tFar;
        ray.mask = ~0u;
        rtcOccluded1(scene_, &context, &ray);
        ++count_;
        // rtcOccluded1 sets tfar to -inf when it finds an occluder and leaves it otherwise.
        return ray.tfar != -std::numeric_limits<float>::infinity();
    }
    uint64_t count() const { return count_; }

private:
    RTCScene scene_;
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

// Visibility of one point of a light: in front of the surface and nothing in between.
bool pointVisible(ShadowRays& rays, const Receiver& r, const glm::dvec3& target) {
    if (!faces(r, target - r.P)) {
        return false;
    }
    const glm::dvec3 toTarget = target - glm::dvec3(r.origin);
    // Stop `offset` short of the target (see the offset derivation). A target closer than
    // that leaves no segment for an occluder to sit on.
    const double tFar = 1.0 - r.offset / glm::length(toTarget);
    return tFar <= 0.0 || rays.unblocked(r.origin, glm::vec3(toTarget), float(tFar));
}

bool directionVisible(ShadowRays& rays, const Receiver& r, const glm::dvec3& towardsLight) {
    return faces(r, towardsLight) &&
           rays.unblocked(r.origin, glm::vec3(towardsLight), std::numeric_limits<float>::infinity());
}

// Fraction of n x n stratified samples of the light that are visible.
float areaVisibility(ShadowRays& rays, const Receiver& r, const AreaLightFrame& frame, int n,
                     Pcg32 rng) {
    int visible = 0;
    for (int b = 0; b < n; ++b) {
        for (int a = 0; a < n; ++a) {
            // Draw the jitter for every stratum, so sample positions never depend on geometry.
            const glm::dvec3 target = areaLightPoint(frame, jitteredSample(a, b, n, rng));
            visible += pointVisible(rays, r, target);
        }
    }
    return float(visible) / float(n * n);
}

// Everything about the light that is the same for every pixel.
struct LightQuery {
    const Light& light;
    AreaLightFrame frame;
    ReferenceOptions options;
};

float pixelVisibility(ShadowRays& rays, const LightQuery& q, const Receiver& r, uint64_t pixel) {
    switch (q.light.type) {
        case LightType::Point:
            return pointVisible(rays, r, glm::dvec3(q.light.position)) ? 1.0f : 0.0f;
        case LightType::Spot:
            return insideSpotCone(q.light, glm::vec3(r.P)) &&
                           pointVisible(rays, r, glm::dvec3(q.light.position))
                       ? 1.0f
                       : 0.0f;
        case LightType::Directional:
            return directionVisible(rays, r, glm::dvec3(q.light.direction)) ? 1.0f : 0.0f;
        case LightType::Disk:
        case LightType::Rectangle:
            return areaVisibility(rays, r, q.frame, q.options.areaSamplesPerAxis,
                                  Pcg32(q.options.seed, pixel));
    }
    return 0.0f;
}

}  // namespace

ReferenceVisibility::ReferenceVisibility(const WorldGeometry& world)
    : embree_(std::make_unique<Embree>()), sceneDiagonal_(sceneDiagonal(world)) {
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
        attachTriangles(embree_->device, embree_->scene, world);
    }
    rtcCommitScene(embree_->scene);
    throwIfEmbreeError(embree_->device, "building the scene");
}

ReferenceVisibility::~ReferenceVisibility() = default;

bool ReferenceVisibility::directionVisible(const glm::vec3& P, const glm::vec3& N, const glm::dvec3& direction) const {
    ShadowRays rays(embree_->scene);
    return shadowlab::directionVisible(rays, receiverAt(P, N, sceneDiagonal_), direction);
}

bool ReferenceVisibility::pointVisible(const glm::vec3& P, const glm::vec3& N, const glm::dvec3& target) const {
    ShadowRays rays(embree_->scene);
    return shadowlab::pointVisible(rays, receiverAt(P, N, sceneDiagonal_), target);
}

std::vector<float> ReferenceVisibility::visibility(const GBuffer& gbuffer, const Light& light,
                                                   const ReferenceOptions& options) const {
    requireConsistent(gbuffer, "ReferenceVisibility::visibility");
    const bool area = light.type == LightType::Disk || light.type == LightType::Rectangle;
    if (area && options.areaSamplesPerAxis < 1) {
        throw std::invalid_argument("ReferenceVisibility: areaSamplesPerAxis must be >= 1");
    }
    const LightQuery query{light, area ? areaLightFrame(light) : AreaLightFrame{}, options};
    std::vector<float> V(gbuffer.pixelCount(), 0.0f);
    const ProgressStage progress(options.progress, "reference rays: row", uint64_t(gbuffer.height));
    tbb::parallel_for(tbb::blocked_range<int>(0, gbuffer.height), [&](const tbb::blocked_range<int>& rows) {
        ShadowRays rays(embree_->scene);
        for (int j = rows.begin(); j != rows.end(); ++j) {
            for (int i = 0; i < gbuffer.width; ++i) {
                const size_t k = gbuffer.index(i, j);
                if (!gbuffer.hit[k]) {
                    continue;
                }
                V[k] = pixelVisibility(rays, query,
                                       receiverAt(gbuffer.position[k], gbuffer.normal[k], sceneDiagonal_), k);
            }
            progress.advance();
        }
        raysCast_ += rays.count();  // integer sum: the total is the same in any order
    });
    return V;
}

}  // namespace shadowlab
