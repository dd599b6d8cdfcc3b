// The soft-shadow cases of Cai et al. 2006 (assets/scenes/soft/*.json, docs/hard-cases.md, "Soft
// shadows") load under a disk light, and each contains its situation; the geometry is
// checked here, the images by eye.
#include <algorithm>
#include <cmath>
#include <string>

#include <doctest/doctest.h>
#include <glm/glm.hpp>

#include "scenes/scene_file.h"
#include "tests/scenes/instance_bounds.h"

using namespace shadowlab;
using shadowlab::test::Box;
using shadowlab::test::instanceBounds;

namespace {

Scene loadSoftCase(const std::string& name) { return loadScene(builtinSceneDir() + "/soft/" + name + ".json"); }

// Unit normal of the first triangle of the instance called name.
glm::vec3 firstNormal(const Scene& scene, const WorldGeometry& world, const std::string& name) {
    for (size_t t = 0; t < world.triangles.size(); ++t) {
        if (scene.instances[world.triangleInstance[t]].name != name) continue;
        const glm::vec3 a = world.positions[world.triangles[t][0]], b = world.positions[world.triangles[t][1]],
                        c = world.positions[world.triangles[t][2]];
        return glm::normalize(glm::cross(b - a, c - a));
    }
    FAIL("no instance " << name);
    return {};
}

}  // namespace

TEST_CASE("soft cases: each loads at 640 x 400 under one disk light") {
    for (const char* name : {"large-light", "tilted-receiver", "two-boxes", "sharp-corner"}) {
        CAPTURE(name);
        const Scene scene = loadSoftCase(name);
        REQUIRE(scene.lights.size() == 1);
        CHECK(scene.lights[0].type == LightType::Disk);
        CHECK(scene.camera.width == 640);
        CHECK(scene.camera.height == 400);
    }
}

TEST_CASE("large-light: the sphere's umbra cone ends above the ground") {
    const Scene scene = loadSoftCase("large-light");
    const Box sphere = instanceBounds(scene, flatten(scene), "sphere");
    const glm::dvec3 centre = (glm::dvec3(sphere.lo) + glm::dvec3(sphere.hi)) * 0.5;
    const double r = 0.5 * double(sphere.hi.y - sphere.lo.y), lightRadius = scene.lights[0].radius;
    const glm::dvec3 light = scene.lights[0].position;
    // Similar triangles: the cone tangent to the disk and the sphere closes D r / (R - r) behind the sphere.
    const double distance = glm::length(centre - light), umbraLength = distance * r / (lightRadius - r);
    const glm::dvec3 tip = centre + (centre - light) / distance * umbraLength;
    CHECK(lightRadius > 3.0 * r);
    CHECK(tip.y > 0.3);
}

TEST_CASE("tilted-receiver: the ramp meets the light's plane at 30 degrees") {
    const Scene scene = loadSoftCase("tilted-receiver");
    const glm::vec3 ramp = firstNormal(scene, flatten(scene), "ramp");
    const double cosine = std::abs(glm::dot(glm::dvec3(ramp), glm::dvec3(scene.lights[0].direction)));
    CHECK(std::acos(cosine) * 180.0 / M_PI == doctest::Approx(30.0).epsilon(1e-4));
}

TEST_CASE("two-boxes: a 2 cm gap, the shadows overlap in depth") {
    const Scene scene = loadSoftCase("two-boxes");
    const WorldGeometry world = flatten(scene);
    const Box left = instanceBounds(scene, world, "left"), right = instanceBounds(scene, world, "right");
    CHECK(right.lo.x - left.hi.x == doctest::Approx(0.02).epsilon(1e-4));
    CHECK(std::min(left.hi.z, right.hi.z) - std::max(left.lo.z, right.lo.z) > 0.5f);
}

TEST_CASE("sharp-corner: star points narrower than 30 degrees") {
    const Scene scene = loadSoftCase("sharp-corner");
    const Mesh& star = scene.meshes[scene.instances[1].mesh];
    // Outer radius R and inner radius r of the star's outline (the centre vertices excluded).
    double outer = 0.0, inner = INFINITY;
    for (const glm::vec3& p : star.positions) {
        const double radius = std::hypot(double(p.x), double(p.z));
        if (radius == 0.0) continue;
        outer = std::max(outer, radius);
        inner = std::min(inner, radius);
    }
    // The tip lies on the outer circle between two inner vertices 36 degrees to either side.
    const double s = std::sin(M_PI / 5), c = std::cos(M_PI / 5);
    const double tipDegrees = 2.0 * std::atan(inner * s / (outer - inner * c)) * 180.0 / M_PI;
    CHECK(tipDegrees < 30.0);
    CHECK(tipDegrees > 20.0);
}

TEST_CASE("sun-disk: a 2.5-degree sun whose penumbra at the post's tip is over 30 cm") {
    const Scene scene = loadSoftCase("sun-disk");
    REQUIRE(scene.lights.size() == 1);
    const Light& sun = scene.lights[0];
    CHECK(sun.type == LightType::Directional);
    CHECK(sun.angularDiameterDeg == 2.5f);
    const Box post = instanceBounds(scene, flatten(scene), "post");
    // From the tip (height H) along the sun to the ground: H / sin(elevation); the penumbra
    // is that length times the angle in radians.
    const double elevation = std::asin(double(sun.direction.y)), angle = 2.5 * M_PI / 180.0;
    CHECK(double(post.hi.y) / std::sin(elevation) * angle > 0.3);
}
