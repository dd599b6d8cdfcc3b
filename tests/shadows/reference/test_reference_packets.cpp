// The reference's rays traced together as a coherent stream (RayQueries::Stream, packets in
// Embree) against its plain twin, one rtcOccluded1 per ray (RayQueries::Single): the same
// bytes of V and of the light passed per channel, on scenes and lights of every kind, and
// through casters that are not opaque, whose occlusion filter then runs on packets
// (RTCFilterFunctionNArguments with N > 1): cut-out cards, a tinted glass, hair and smoke.
// A broken lane bookkeeping in the filter (a crossing credited to another ray) or a
// packet path that lets a ray slip through a seam changes the bytes. Closest-hit queries
// likewise, and their light is the occlusion queries'.
#include <doctest/doctest.h>

#include <cmath>
#include <span>
#include <string>
#include <vector>

#include "scenes/scene_file.h"
#include "shading/lights.h"
#include "shadows/camera_pass.h"
#include "shadows/reference/reference.h"
#include "tests/same_bits.h"

using namespace shadowlab;

namespace {

std::string packetSceneFile(const std::string& name) { return std::string(SHADOWLAB_SOURCE_DIR) + "/assets/scenes/" + name + ".json"; }

// A scene at a small size, its G-buffer and the reference's rays through its casters.
struct PacketScene {
    Scene scene;
    WorldGeometry world;
    GBuffer gbuffer;
    CasterTransmission transmission;
    ReferenceVisibility reference;
    explicit PacketScene(const std::string& name)
        : scene(smallCopy(loadScene(packetSceneFile(name)))), world(flatten(scene)),
          gbuffer(renderGBuffer(world, scene.camera, raster::SimdLevel::Scalar)), transmission(scene, world),
          reference(world, &transmission) {}
    static Scene smallCopy(Scene s) {
        s.camera.width = 48, s.camera.height = 30;
        return s;
    }
};

// The same light as `light` seen as each other kind: point and spot at its position, a
// directional light from above it, point-like and as a sun of 3 degrees (its cap of
// directions), a disk and a rectangle of the scene's scale around it.
std::vector<Light> everyKind(const Light& light, float size) {
    const glm::vec3 centre = light.position;
    const glm::vec3 down = glm::normalize(-centre + glm::vec3(0.0f, 0.0f, 0.1f));
    return {
        {.type = LightType::Point, .position = centre},
        {.type = LightType::Spot, .position = centre, .direction = down, .coneAngleDeg = 25.0f},
        {.type = LightType::Directional, .direction = glm::normalize(centre)},
        {.type = LightType::Directional, .direction = glm::normalize(centre), .angularDiameterDeg = 3.0f},
        {.type = LightType::Disk, .position = centre, .direction = -down, .radius = size},
        {.type = LightType::Rectangle, .position = centre, .halfEdgeU = {size, 0.0f, 0.0f}, .halfEdgeV = {0.0f, 0.0f, 0.6f * size}},
    };
}

void checkSameAsSingleRays(const PacketScene& s, const Light& light) {
    const ReferenceOptions stream{.areaSamplesPerAxis = 8, .queries = RayQueries::Stream};
    ReferenceOptions single = stream;
    single.queries = RayQueries::Single;
    const ReferenceVisibility::Passed a = s.reference.passed(s.gbuffer, light, stream);
    const ReferenceVisibility::Passed b = s.reference.passed(s.gbuffer, light, single);
    CHECK(test::sameBytes(a.visibility, b.visibility));
    CHECK(test::sameBytes(a.coloured, b.coloured));
}

// Traced for their first occluders, a pixel sequence's rays (shadows/raytraced/) bring the
// light occlusion queries of the same samples bring, and a stream and single rays find the
// same occluders: the closest-hit filter's bookkeeping and the distances' planes.
void checkClosestHitsSameAsSingleRays(const PacketScene& s, const Light& light) {
    const ReferenceOptions occlusion{.queries = RayQueries::Stream, .sequence = PixelSequence{.count = 4, .frame = 3}};
    ReferenceOptions stream = occlusion, single = occlusion;
    stream.occluderDistance = single.occluderDistance = true;
    single.queries = RayQueries::Single;
    const ReferenceVisibility::Passed a = s.reference.passed(s.gbuffer, light, occlusion);
    const ReferenceVisibility::Passed b = s.reference.passed(s.gbuffer, light, stream);
    const ReferenceVisibility::Passed c = s.reference.passed(s.gbuffer, light, single);
    CHECK(test::sameBytes(a.visibility, b.visibility));
    CHECK(test::sameBytes(a.coloured, b.coloured));
    CHECK(test::sameBytes(b.visibility, c.visibility));
    CHECK(test::sameBytes(b.occluderDistance, c.occluderDistance));
    CHECK(test::sameBytes(b.occludedRays, c.occludedRays));
}

}  // namespace

TEST_CASE("reference: the stream of rays gives the bytes of single rays, every light kind, opaque and not") {
    const std::vector<std::string> scenes = {"sphere-box",
                                             "bunny",
                                             "soft/branch-over-crate",
                                             "volumetric/foliage-cards",
                                             "volumetric/tinted-glass",
                                             "volumetric/hair-over-plane",
                                             "volumetric/smoke-over-plane"};
    for (const std::string& name : scenes) {
        const PacketScene s(name);
        REQUIRE(!s.scene.lights.empty());
        const Light& own = s.scene.lights[0];
        const float size = 0.05f * float(sceneDiagonal(s.world));
        CAPTURE(name);
        checkSameAsSingleRays(s, own);
        checkClosestHitsSameAsSingleRays(s, own);
        const Light anchor{.position = own.type == LightType::Directional ? 10.0f * own.direction : own.position};
        for (const Light& light : everyKind(anchor, size)) {
            CAPTURE(int(light.type));
            checkSameAsSingleRays(s, light);
            checkClosestHitsSameAsSingleRays(s, light);
        }
    }
}

TEST_CASE("reference: directionsPassed traced together gives each direction's directionPassed") {
    const PacketScene s("volumetric/foliage-cards");
    REQUIRE(s.transmission.anyNonOpaque());
    ReferenceVisibility::RayBatch batch;
    std::vector<glm::dvec3> directions;
    for (int k = 0; k < 40; ++k) {   // a fan over the sky, some below the surface's plane
        const double a = 0.15 * k;
        directions.push_back(glm::normalize(glm::dvec3(std::cos(a), 0.8 - 0.04 * k, std::sin(a))));
    }
    int compared = 0;
    for (size_t k = 0; k < s.gbuffer.pixelCount(); k += 7) {
        if (!s.gbuffer.hit[k]) continue;
        const glm::vec3 P = s.gbuffer.position[k], N = s.gbuffer.normal[k];
        const std::span<const glm::vec3> passed = s.reference.directionsPassed(P, N, directions, batch);
        const std::vector<glm::vec3> together(passed.begin(), passed.end());
        std::vector<glm::vec3> alone;
        for (const glm::dvec3& d : directions) alone.push_back(s.reference.directionPassed(P, N, d));
        CHECK(test::sameBytes(together, alone));
        ++compared;
    }
    CHECK(compared > 20);
}
