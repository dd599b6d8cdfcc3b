// Motion vectors (shading/motion_vectors.h) and reprojection with its disocclusion tests
// (shadows/temporal/reprojection.h), against what a camera move and an object's move give
// analytically, and against the previous frame's own G-buffer.
#include <doctest/doctest.h>

#include <cmath>

#include "scenes/camera.h"
#include "shadows/camera_pass.h"
#include "shadows/temporal/reprojection.h"
#include "temporal_test_support.h"

using namespace shadowlab;
using namespace shadowlab::temporal_test;

namespace {

GBuffer viewOf(const PreparedScene& prepared) {
    return renderGBuffer(prepared.world(), prepared.scene().camera, raster::bestSimdLevel());
}

}  // namespace

TEST_CASE("a still view has zero motion and keeps every pixel's history in place") {
    const PreparedScene prepared(loadSmall("sphere-box.json", 64, 40));
    GBuffer g = viewOf(prepared);
    const PreviousView before = keepView(g, prepared.scene());
    g.motion = surfaceMotion(g, prepared.world(), prepared.scene(), before);
    const Reprojection r = reproject(g, before, {});
    CHECK(r.rejectedPixels == 0);
    for (size_t k = 0; k < g.pixelCount(); ++k) {
        if (!g.hit[k]) continue;
        REQUIRE(g.motion.pixelOffset[k] == glm::vec2(0.0f));
        REQUIRE(g.motion.previousPosition[k] == g.position[k]);
        REQUIRE(r.texels[k].x == k);
        REQUIRE(r.weights[k] == glm::vec4(1.0f, 0.0f, 0.0f, 0.0f));
    }
}

TEST_CASE("a camera moved sideways gives each point the shift its depth says") {
    // A point at depth z along the view axis moves by d f / z pixels when the camera moves d
    // to its right, f = H / (2 tan(fovy / 2)) the focal length in pixels; in the frame
    // before, the camera was to the left, so the point was further right: offset +d f / z.
    PreparedScene prepared(loadSmall("sphere-box.json", 96, 60));
    const Camera now = prepared.scene().camera;
    const glm::dvec3 forward = glm::normalize(glm::dvec3(now.target - now.eye));
    const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(now.up)));
    const double d = 0.05;
    Camera then = now;
    then.eye -= glm::vec3(right * d), then.target -= glm::vec3(right * d);
    prepared.setCamera(then);
    const PreviousView before = keepView(viewOf(prepared), prepared.scene());
    prepared.setCamera(now);
    GBuffer g = viewOf(prepared);
    g.motion = surfaceMotion(g, prepared.world(), prepared.scene(), before);
    const double focal = now.height / (2.0 * std::tan(glm::radians(double(now.fovyDeg)) / 2.0));
    int checked = 0;
    for (size_t k = 0; k < g.pixelCount(); ++k) {
        if (!g.hit[k]) continue;
        const double z = glm::dot(glm::dvec3(g.position[k]) - glm::dvec3(now.eye), forward);
        REQUIRE(g.motion.pixelOffset[k].x == doctest::Approx(d * focal / z).epsilon(1e-4));
        REQUIRE(std::abs(g.motion.pixelOffset[k].y) < 1e-3);
        ++checked;
    }
    CHECK(checked > 1000);
}

TEST_CASE("a moving sphere's points are carried back onto the sphere where it was") {
    const Scene base = loadSmall("flythrough/sliding-sphere.json", 96, 60);
    PreparedScene prepared{Scene(base)};
    placeAtPathFrame(prepared, base, 3, 12);
    const uint32_t sphere = 1;
    const glm::vec3 centreBefore = glm::vec3(prepared.scene().instances[sphere].worldFromObject[3]);
    const std::vector<glm::vec3> positionsBefore = prepared.world().positions;
    const PreviousView before = keepView(viewOf(prepared), prepared.scene());
    placeAtPathFrame(prepared, base, 4, 12);
    GBuffer g = viewOf(prepared);
    g.motion = surfaceMotion(g, prepared.world(), prepared.scene(), before);
    int onSphere = 0;
    for (size_t k = 0; k < g.pixelCount(); ++k) {
        if (!g.hit[k]) continue;
        if (prepared.world().triangleInstance[g.triangle[k]] == sphere) {
            // The uv-sphere's facets lie within 0.2% of its radius 1 of the centre.
            REQUIRE(glm::length(g.motion.previousPosition[k] - centreBefore) == doctest::Approx(1.0).epsilon(3e-3));
            REQUIRE(glm::length(g.motion.previousNormal[k]) == doctest::Approx(1.0).epsilon(1e-5));
            // Turned with the sphere: the normal of the same triangle where it was the frame
            // before (an unturned one is 8 degrees off: the sphere turns 90 degrees in 11 frames).
            const glm::uvec3 tri = prepared.world().triangles[g.triangle[k]];
            const glm::dvec3 a(positionsBefore[tri.x]), b(positionsBefore[tri.y]), c(positionsBefore[tri.z]);
            const glm::dvec3 facet = glm::normalize(glm::cross(b - a, c - a));
            REQUIRE(std::abs(glm::dot(glm::dvec3(g.motion.previousNormal[k]), facet)) > 1.0 - 1e-5);
            ++onSphere;
        } else {
            REQUIRE(g.motion.previousPosition[k] == g.position[k]);   // the ground and the box stay
            REQUIRE(g.motion.pixelOffset[k] == glm::vec2(0.0f));     // and so does the camera
        }
    }
    CHECK(onSphere > 200);
}

TEST_CASE("reprojection rejects exactly the ground a moving sphere uncovered") {
    // The camera stays, so a ground pixel's history is its own pixel in the frame before:
    // kept where the ground was seen there, rejected where the sphere (or the box) was.
    const Scene base = loadSmall("flythrough/sliding-sphere.json", 96, 60);
    PreparedScene prepared{Scene(base)};
    placeAtPathFrame(prepared, base, 3, 12);
    const GBuffer previous = viewOf(prepared);
    const PreviousView before = keepView(previous, prepared.scene());
    placeAtPathFrame(prepared, base, 4, 12);
    GBuffer g = viewOf(prepared);
    g.motion = surfaceMotion(g, prepared.world(), prepared.scene(), before);
    const Reprojection r = reproject(g, before, {});
    const std::vector<uint32_t>& instanceOf = prepared.world().triangleInstance;
    size_t uncovered = 0, sphereKept = 0, sphere = 0;
    for (size_t k = 0; k < g.pixelCount(); ++k) {
        if (!g.hit[k]) continue;
        const uint32_t now = instanceOf[g.triangle[k]];
        if (now == 1) {
            ++sphere, sphereKept += r.kept[k];
            continue;
        }
        const bool seenBefore = previous.hit[k] && instanceOf[previous.triangle[k]] == now;
        INFO("pixel " << k);
        REQUIRE(bool(r.kept[k]) == seenBefore);
        uncovered += !seenBefore;
    }
    CHECK(uncovered > 20);
    // Most of the sphere was in view the frame before, a little further left.
    CHECK(double(sphereKept) > 0.8 * double(sphere));
    CHECK(r.rejectedPixels >= uncovered);
    CHECK(r.rejectedPixels <= uncovered + (sphere - sphereKept));
}

TEST_CASE("reprojection refuses a G-buffer without motion and bad settings") {
    const PreparedScene prepared(loadSmall("sphere-box.json", 16, 10));
    GBuffer g = viewOf(prepared);
    const PreviousView before = keepView(g, prepared.scene());
    CHECK_THROWS_AS(reproject(g, before, {}), std::invalid_argument);
    g.motion = surfaceMotion(g, prepared.world(), prepared.scene(), before);
    CHECK_THROWS_AS(reproject(g, before, {.planeTolerance = 0.0}), std::invalid_argument);
    CHECK_THROWS_AS(reproject(g, before, {.minNormalCos = 2.0}), std::invalid_argument);
}
