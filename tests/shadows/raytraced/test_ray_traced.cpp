// ray-traced: N Embree rays per pixel with samples that move on from frame to frame, and
// the occluder distance.
//  - one ray per pixel through opaque casters gives V in {0, 1}, and its mean over 64
//    frames approaches reference-soft: each frame's samples are the next points of the
//    pixel's shifted (0, 2)-sequence, so 64 frames are 64 samples of the light, whose mean
//    is within 0.5 / sqrt(64) = 0.0625 RMS of the visible fraction even for independent
//    samples (a variance p (1 - p) <= 1/4 per sample), plus the reference's own error,
//    1024 strata: at most 0.5 / 32 = 0.016;
//  - 256 rays per pixel: within 0.5 / 16 + 0.016 = 0.047 RMS of reference-soft by the same
//    argument, and the measured figure far below it;
//  - towards a point light, and a point-like sun, every ray count gives `reference`'s bytes;
//  - the occluder distance over a square above a plane is the height along the ray, h /
//    cos(theta), to the ray offset and float precision, for a point light and, between its
//    bounds, a disk;
//  - frames differ, frame k is the same bytes on every run, thread count and SIMD level,
//    and a frame alone is frame 0;
//  - bad settings are refused.
#include <doctest/doctest.h>

#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "frame/registry.h"
#include "raster/thread_count.h"
#include "shadows/raytraced/shadow_rays.h"
#include "shadows/reference/scene_rays.h"
#include "tests/shadows/shadow_test_support.h"
#include "tests/shadows/soft_test_support.h"

using namespace shadowlab;

namespace {

ShadowOutputs runRays(const test::SoftScene& s, const Light& light, int rays, uint64_t frame = 0,
                      raster::SimdLevel simd = raster::bestSimdLevel()) {
    const Technique& t = findTechnique("ray-traced");
    const TechniqueParams params(t.name, t.params, {{"rays", std::to_string(rays)}});
    return t.run({.prepared = s.prepared, .gbuffer = s.gbuffer, .light = light, .simd = simd, .params = params,
                  .frameIndex = frame});
}

test::SoftScene squareScene() { return test::SoftScene(test::smallScene(test::softCase("square-over-plane"), 160, 100)); }

}  // namespace

TEST_CASE("ray-traced: one ray is 0 or 1, and 64 frames of it approach reference-soft") {
    const test::SoftScene s = squareScene();
    std::vector<double> sum(s.gbuffer.pixelCount(), 0.0);
    double firstRms = 0.0;
    const int frames = 64;
    for (int f = 0; f < frames; ++f) {
        const ShadowOutputs out = runRays(s, s.scene.lights[0], 1, uint64_t(f));
        CHECK(test::stat(out, "frame_count") == f);
        for (size_t k = 0; k < sum.size(); ++k) {
            REQUIRE((out.visibility[k] == 0.0f || out.visibility[k] == 1.0f));
            sum[k] += out.visibility[k];
        }
        if (f == 0) firstRms = s.rms(out.visibility);
    }
    std::vector<float> mean(sum.size());
    for (size_t k = 0; k < sum.size(); ++k) mean[k] = float(sum[k] / frames);
    const double meanRms = s.rms(mean);
    INFO("one frame's RMS " << firstRms << ", 64 frames' " << meanRms);
    CHECK(meanRms < 0.0625 + 0.016);
    CHECK(meanRms < firstRms / 4.0);   // sqrt(64) = 8 for independent samples
}

TEST_CASE("ray-traced: 256 rays are close to reference-soft") {
    const test::SoftScene s = squareScene();
    const ShadowOutputs out = runRays(s, s.scene.lights[0], 256);
    INFO("RMS " << s.rms(out.visibility));
    CHECK(s.rms(out.visibility) < 0.047);
    CHECK(test::stat(out, "rays_per_pixel") == 256.0);
    CHECK(test::stat(out, "rays_cast_count") > 256.0 * 1000.0);
}

TEST_CASE("ray-traced: towards a point light or a point-like sun, the reference's bytes at any ray count") {
    const test::SoftScene s = squareScene();
    const Light& own = s.scene.lights[0];
    const Light sun{.type = LightType::Directional, .direction = glm::normalize(own.position)};
    for (const Light& light : {pointLightFor(own), sun}) {
        const ReferenceVisibility& rays = sceneRays(s.prepared);
        const std::vector<float> exact = rays.visibility(s.gbuffer, light);
        for (int n : {1, 7, 64}) {
            CAPTURE(n);
            const ShadowOutputs out = runRays(s, light, n);
            CHECK(test::sameBytes(out.visibility, exact));
            // One ray per pixel that faces the light, whatever N.
            CHECK(test::stat(out, "rays_cast_count") <= double(s.gbuffer.pixelCount()));
        }
    }
}

namespace {

// A 1 m square at height h over the plane y = 0, and a grid of points on the plane.
struct SquareOverPlane {
    static constexpr double h = 0.75;
    WorldGeometry world;
    GBuffer g;
    SquareOverPlane() {
        const auto quad = [this](const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& d) {
            const uint32_t base = uint32_t(world.positions.size());
            world.positions.insert(world.positions.end(), {a, b, c, d});
            world.triangles.push_back({base, base + 1, base + 2});
            world.triangles.push_back({base, base + 2, base + 3});
            world.triangleMaterial.insert(world.triangleMaterial.end(), 2, 0);
            world.triangleInstance.insert(world.triangleInstance.end(), 2, 0);
        };
        const float y = float(h);
        quad({-5, 0, -5}, {-5, 0, 5}, {5, 0, 5}, {5, 0, -5});
        quad({-0.5f, y, -0.5f}, {-0.5f, y, 0.5f}, {0.5f, y, 0.5f}, {0.5f, y, -0.5f});
        const int n = 41;
        g.width = g.height = n;
        const size_t count = g.pixelCount();
        g.hit.assign(count, 1), g.material.assign(count, 0), g.triangle.assign(count, 0), g.depth.assign(count, 0.5f);
        g.normal.assign(count, glm::vec3(0, 1, 0)), g.shadingNormal = g.normal;
        for (int j = 0; j < n; ++j) {
            for (int i = 0; i < n; ++i) g.position.push_back(glm::vec3(-1.5f + 3.0f * i / (n - 1), 0.0f, -1.5f + 3.0f * j / (n - 1)));
        }
    }
};

}  // namespace

TEST_CASE("ray-traced: the occluder distance over a square is the height along the ray") {
    const SquareOverPlane s;
    const ReferenceVisibility rays(s.world, nullptr);
    SUBCASE("a point light: h / cos(theta) where the ray meets the square, 0 where it does not") {
        const Light light{.type = LightType::Point, .position = {0.3f, 3.0f, -0.2f}};
        const ShadowRayBuffers out = traceShadowRays(rays, s.g, light, 4, 0);
        int occluded = 0;
        for (size_t k = 0; k < s.g.pixelCount(); ++k) {
            const glm::dvec3 P(s.g.position[k]), L(light.position);
            const glm::dvec3 Q = P + (SquareOverPlane::h / L.y) * (L - P);   // the ray at the square's height
            const double outside = std::max(std::abs(Q.x), std::abs(Q.z)) - 0.5;
            if (std::abs(outside) < 1e-3) continue;   // the outline: either answer
            CAPTURE(k);
            CHECK(out.occludedRays[k] == (outside < 0.0 ? 1u : 0u));
            CHECK(out.visibility[k] == (outside < 0.0 ? 0.0f : 1.0f));
            if (outside > 0.0) {
                CHECK(out.occluderDistance[k] == 0.0f);
                continue;
            }
            // The ray leaves P moved by the shadow-ray offset along N, and its direction
            // is rounded to float: the distance is good to an offset and a few float ulps.
            const double expected = glm::length(Q - P);
            CHECK(std::abs(out.occluderDistance[k] - expected) <= rays.shadowRayOffset(s.g.position[k]) + 4e-7 * expected);
            ++occluded;
        }
        CHECK(occluded > 50);
    }
    SUBCASE("a disk light: the mean over the occluded rays lies between the vertical and the steepest ray's") {
        const Light light{.type = LightType::Disk, .position = {0.0f, 3.0f, 0.0f}, .direction = {0.0f, -1.0f, 0.0f},
                          .radius = 0.4f};
        const ShadowRayBuffers out = traceShadowRays(rays, s.g, light, 16, 5);
        int occluded = 0;
        for (size_t k = 0; k < s.g.pixelCount(); ++k) {
            if (out.occludedRays[k] == 0) continue;
            const glm::dvec3 P(s.g.position[k]);
            const double reach = glm::length(glm::dvec2(P.x, P.z)) + light.radius;   // the farthest point of the disk, sideways
            const double steepest = SquareOverPlane::h * std::sqrt(1.0 + reach * reach / (3.0 * 3.0));
            CAPTURE(k);
            CHECK(out.occluderDistance[k] >= SquareOverPlane::h * (1.0 - 1e-6));
            CHECK(out.occluderDistance[k] <= steepest * (1.0 + 1e-6));
            CHECK(out.visibility[k] == 1.0f - float(out.occludedRays[k]) / 16.0f);
            const float angle = 2.0f * float(std::asin(light.radius / glm::length(glm::dvec3(light.position) - P)));
            CHECK(out.lightAngle[k] == doctest::Approx(angle).epsilon(1e-6));
            ++occluded;
        }
        CHECK(occluded > 50);
    }
}

TEST_CASE("ray-traced: frames differ, and frame k is the same bytes on every run, thread count and SIMD level") {
    const test::SoftScene s = squareScene();
    const Light& light = s.scene.lights[0];
    const ReferenceVisibility& rays = sceneRays(s.prepared);
    std::vector<ShadowRayBuffers> frames;
    for (uint32_t f = 0; f < 3; ++f) frames.push_back(traceShadowRays(rays, s.gbuffer, light, 4, f));
    CHECK_FALSE(test::sameBytes(frames[0].visibility, frames[1].visibility));
    CHECK_FALSE(test::sameBytes(frames[1].occluderDistance, frames[2].occluderDistance));
    for (int threads : {1, 2}) {
        CAPTURE(threads);
        for (uint32_t f = 0; f < 3; ++f) {
            const ShadowRayBuffers again = withThreads(threads, [&] { return traceShadowRays(rays, s.gbuffer, light, 4, f); });
            CHECK(test::sameBytes(again.visibility, frames[f].visibility));
            CHECK(test::sameBytes(again.occluderDistance, frames[f].occluderDistance));
            CHECK(test::sameBytes(again.occludedRays, frames[f].occludedRays));
            CHECK(test::sameBytes(again.lightAngle, frames[f].lightAngle));
        }
    }
    // The technique samples at its frame's index (ShadowInputs::frameIndex); a frame alone is frame 0.
    for (raster::SimdLevel level : {raster::SimdLevel::Scalar, raster::bestSimdLevel()}) {
        for (uint32_t f = 0; f < 3; ++f) CHECK(test::sameBytes(runRays(s, light, 4, f, level).visibility, frames[f].visibility));
    }
}

TEST_CASE("ray-traced: bad settings are refused") {
    const Technique& t = findTechnique("ray-traced");
    for (const std::string bad : {"0", "1025", "-3", "many"}) {
        CAPTURE(bad);
        CHECK_THROWS_AS(TechniqueParams(t.name, t.params, {{"rays", bad}}), std::invalid_argument);
    }
    const SquareOverPlane s;
    const ReferenceVisibility rays(s.world, nullptr);
    const Light disk{.type = LightType::Disk, .position = {0.0f, 3.0f, 0.0f}, .direction = {0.0f, -1.0f, 0.0f}, .radius = 0.4f};
    CHECK_THROWS_WITH_AS(traceShadowRays(rays, s.g, disk, 0, 0), "ray-traced shadows: rays per pixel must be >= 1",
                         std::invalid_argument);
}
