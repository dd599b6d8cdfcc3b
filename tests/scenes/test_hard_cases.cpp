// The hard-case scenes (assets/scenes/hard/*.json, docs/hard-cases.md) load, and each one really
// contains the situation it is named after: the geometry is checked here, not the images.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <doctest/doctest.h>
#include <glm/glm.hpp>

#include "scenes/camera.h"
#include "scenes/scene_file.h"
#include "tests/scenes/instance_bounds.h"

using namespace shadowlab;
using shadowlab::test::Box;
using shadowlab::test::instanceBounds;

namespace {

const std::vector<std::string> kHardCases = {
    "box-contact", "camera-in-shadow", "coincident-faces", "grazing-light", "huge-depth-range", "light-close",
    "near-plane-cuts-volume", "open-mesh", "point-light-inside", "sphere-terminator", "spot", "sun",
    "thin-occluder"};

// Hard cases are not built-in scenes: they load by path (docs/hard-cases.md).
Scene loadHardCase(const std::string& name) {
    return loadScene(builtinSceneDir() + "/hard/" + name + ".json");
}

// Slab test: does the segment from a to b pass through the inside of box?
bool segmentHitsBox(glm::dvec3 a, glm::dvec3 b, const Box& box) {
    double enter = 0.0, leave = 1.0;
    for (int axis = 0; axis < 3; ++axis) {
        const double d = b[axis] - a[axis];
        if (d == 0.0) {
            if (a[axis] <= box.lo[axis] || a[axis] >= box.hi[axis]) return false;
            continue;
        }
        const double t0 = (box.lo[axis] - a[axis]) / d, t1 = (box.hi[axis] - a[axis]) / d;
        enter = std::max(enter, std::min(t0, t1));
        leave = std::min(leave, std::max(t0, t1));
    }
    return enter < leave;
}

// Inside the camera's view frustum (between near and far, within the image)?
bool inFrustum(const Camera& camera, glm::dvec3 p) {
    const glm::dvec4 clip = clipFromWorldD(camera) * glm::dvec4(p, 1.0);
    return clip.w > 0.0 && std::abs(clip.x) <= clip.w && std::abs(clip.y) <= clip.w && std::abs(clip.z) <= clip.w;
}

double elevationDeg(glm::dvec3 lightPosition, glm::dvec3 groundPoint) {
    const glm::dvec3 toLight = lightPosition - groundPoint;
    return glm::degrees(std::asin(toLight.y / glm::length(toLight)));
}

glm::dvec3 viewDirection(const Camera& camera) {
    return glm::normalize(glm::dvec3(camera.target) - glm::dvec3(camera.eye));
}

}  // namespace

TEST_CASE("every hard case loads, at 640x400, and none is listed as a built-in scene") {
    std::vector<std::string> files;
    for (const auto& entry : std::filesystem::directory_iterator(builtinSceneDir() + "/hard"))
        if (entry.path().extension() == ".json") files.push_back(entry.path().stem().string());
    std::ranges::sort(files);
    CHECK(files == kHardCases);
    const std::vector<std::string> builtins = builtinSceneNames();
    for (const std::string& name : kHardCases) {
        CAPTURE(name);
        const Scene scene = loadHardCase(name);
        CHECK(scene.name == name);
        CHECK(scene.camera.width == 640);
        CHECK(scene.camera.height == 400);
        CHECK(std::ranges::find(builtins, name) == builtins.end());
    }
}

TEST_CASE("grazing-light: the point light is 3 degrees above the origin, 2.7 to 3.4 over the ground") {
    const Scene scene = loadHardCase("grazing-light");
    REQUIRE(scene.lights.size() == 1);
    const Light& light = scene.lights[0];
    CHECK(light.type == LightType::Point);
    CHECK(elevationDeg(light.position, {0, 0, 0}) == doctest::Approx(3.0).epsilon(1e-5));
    for (double x : {-10.0, 10.0})
        for (double z : {-10.0, 10.0}) {
            CHECK(elevationDeg(light.position, {x, 0, z}) > 2.7);
            CHECK(elevationDeg(light.position, {x, 0, z}) < 3.4);
        }
}

TEST_CASE("thin-occluder: a 1 x 0.01 x 1 box lies on the ground") {
    const Scene scene = loadHardCase("thin-occluder");
    const Box plate = instanceBounds(scene, flatten(scene), "plate");
    CHECK(plate.lo.y == 0.0f);
    CHECK(plate.hi.y == 0.01f);
    CHECK(plate.hi.x - plate.lo.x == 1.0f);
    CHECK(plate.hi.z - plate.lo.z == 1.0f);
    // The light is above and to one side, so the visible shadow is a strip along one edge.
    CHECK(scene.lights[0].position.y > 1.0f);
    CHECK(scene.lights[0].position.x > plate.hi.x);
}

TEST_CASE("camera-in-shadow: the slab hides the light from the eye, not from the far ground") {
    const Scene scene = loadHardCase("camera-in-shadow");
    const Box slab = instanceBounds(scene, flatten(scene), "slab");
    const glm::dvec3 light(scene.lights[0].position), eye(scene.camera.eye);
    CHECK(segmentHitsBox(eye, light, slab));
    CHECK(eye.y < slab.lo.y);
    // Ground the camera looks at beyond the shadow's edge (x, z = +-5.33) is lit.
    const glm::dvec3 litGround(0.0, 0.0, -8.0);
    CHECK_FALSE(segmentHitsBox(litGround, light, slab));
    CHECK(inFrustum(scene.camera, litGround));
}

TEST_CASE("near-plane-cuts-volume: the eye lies on a side face of the slab's shadow volume, looking along it") {
    const Scene scene = loadHardCase("near-plane-cuts-volume");
    const Box slab = instanceBounds(scene, flatten(scene), "slab");
    const glm::dvec3 light(scene.lights[0].position), eye(scene.camera.eye);
    // The side face through the slab's top edge at x = max x, swept away from the light.
    const glm::dvec3 edgePoint(slab.hi.x, slab.hi.y, 0.0), edgeDirection(0.0, 0.0, 1.0);
    const glm::dvec3 normal = glm::normalize(glm::cross(edgeDirection, edgePoint - light));
    const double near = scene.camera.zNear;
    CHECK(near == doctest::Approx(0.1));
    CHECK(std::abs(glm::dot(eye - light, normal)) < 1e-3 * near);
    CHECK(std::abs(glm::dot(viewDirection(scene.camera), normal)) < 1e-6);
    // The eye is below the slab, between its near and far z ends, so inside the volume's extent.
    CHECK(eye.y < slab.lo.y);
    CHECK(eye.z > slab.lo.z);
    CHECK(eye.z < slab.hi.z);
}

TEST_CASE("light-close: the point light is 0.05 m above the pillar's top") {
    const Scene scene = loadHardCase("light-close");
    const Box pillar = instanceBounds(scene, flatten(scene), "pillar");
    const glm::vec3 light = scene.lights[0].position;
    CHECK(scene.lights[0].type == LightType::Point);
    CHECK(light.y - pillar.hi.y == doctest::Approx(0.05).epsilon(1e-4));
    CHECK(light.x > pillar.lo.x);
    CHECK(light.x < pillar.hi.x);
    CHECK(light.z > pillar.lo.z);
    CHECK(light.z < pillar.hi.z);
}

TEST_CASE("huge-depth-range: near 0.01, far 10000, occluders from 1.2 m to beyond 5 km") {
    const Scene scene = loadHardCase("huge-depth-range");
    CHECK(scene.camera.zNear == 0.01f);
    CHECK(scene.camera.zFar == 10000.0f);
    const WorldGeometry world = flatten(scene);
    const glm::dvec3 eye(scene.camera.eye);
    double nearest = INFINITY, farthest = 0.0;
    for (size_t t = 0; t < world.triangles.size(); ++t) {
        if (scene.instances[world.triangleInstance[t]].name == "ground") continue;
        for (int c = 0; c < 3; ++c) {
            const double d = glm::length(glm::dvec3(world.positions[world.triangles[t][c]]) - eye);
            nearest = std::min(nearest, d);
            farthest = std::max(farthest, d);
        }
    }
    CHECK(nearest < 1.5);
    CHECK(farthest > 5000.0);
    CHECK(farthest < scene.camera.zFar);
    const Box ground = instanceBounds(scene, world, "ground");
    CHECK(ground.lo.z < -9000.0f);
    CHECK(ground.hi.z > eye.z);
}

TEST_CASE("sphere-terminator: a 256 x 128 sphere lit from the side, the terminator facing the camera") {
    const Scene scene = loadHardCase("sphere-terminator");
    const WorldGeometry world = flatten(scene);
    const Box sphere = instanceBounds(scene, world, "sphere");
    const glm::dvec3 centre = (glm::dvec3(sphere.lo) + glm::dvec3(sphere.hi)) * 0.5;
    size_t sphereTriangles = 0;
    for (uint32_t instance : world.triangleInstance) sphereTriangles += scene.instances[instance].name == "sphere";
    CHECK(sphereTriangles == 256 * 127 * 2);
    const glm::dvec3 toLight = glm::normalize(glm::dvec3(scene.lights[0].position) - centre);
    CHECK(std::abs(toLight.y) < 1e-6);   // horizontal: lit exactly from the side
    CHECK(std::abs(glm::dot(toLight, viewDirection(scene.camera))) < 0.01);
}

TEST_CASE("open-mesh: the teapot has open edges, stands Y up and rests on the ground") {
    const Scene scene = loadHardCase("open-mesh");
    const auto teapot = std::ranges::find(scene.instances, std::string("teapot"), &MeshInstance::name);
    REQUIRE(teapot != scene.instances.end());
    const Mesh& mesh = scene.meshes[teapot->mesh];
    std::map<std::pair<uint32_t, uint32_t>, int> edgeUses;
    for (const glm::uvec3& t : mesh.triangles)
        for (int c = 0; c < 3; ++c) ++edgeUses[std::minmax(t[c], t[(c + 1) % 3])];
    const auto boundaryEdges = std::ranges::count_if(edgeUses, [](const auto& use) { return use.second == 1; });
    CHECK(boundaryEdges == 192);
    const Box bounds = instanceBounds(scene, flatten(scene), "teapot");
    CHECK(std::abs(bounds.lo.y) < 1e-5f);
    CHECK(bounds.hi.y == doctest::Approx(0.4 * 3.15).epsilon(1e-5));
}

TEST_CASE("coincident-faces: two identical quads lie exactly on the ground, in the sphere's shadow") {
    const Scene scene = loadHardCase("coincident-faces");
    const WorldGeometry world = flatten(scene);
    std::map<std::string, std::vector<glm::vec3>> corners;
    for (size_t t = 0; t < world.triangles.size(); ++t) {
        const std::string& name = scene.instances[world.triangleInstance[t]].name;
        if (name.rfind("quad-", 0) != 0) continue;
        for (int c = 0; c < 3; ++c) corners[name].push_back(world.positions[world.triangles[t][c]]);
    }
    REQUIRE(corners.size() == 2);
    CHECK(corners["quad-red"] == corners["quad-blue"]);
    for (const glm::vec3& p : corners["quad-red"]) CHECK(p.y == 0.0f);
    // The sphere's centre projects from the light onto y = 0 inside the quads.
    const Box quad = instanceBounds(scene, world, "quad-red"), sphere = instanceBounds(scene, world, "sphere");
    const glm::dvec3 light(scene.lights[0].position), centre = (glm::dvec3(sphere.lo) + glm::dvec3(sphere.hi)) * 0.5;
    const glm::dvec3 shadow = light + (centre - light) * (light.y / (light.y - centre.y));
    CHECK(shadow.x > quad.lo.x);
    CHECK(shadow.x < quad.hi.x);
    CHECK(shadow.z > quad.lo.z);
    CHECK(shadow.z < quad.hi.z);
}

TEST_CASE("point-light-inside: a closed room facing inwards, a visible shadow on every cube face") {
    const Scene scene = loadHardCase("point-light-inside");
    const WorldGeometry world = flatten(scene);
    const glm::dvec3 light(scene.lights[0].position);
    const Box room{{-3, 0, -3}, {3, 3, 3}};
    CHECK(glm::all(glm::greaterThan(light, glm::dvec3(room.lo))));
    CHECK(glm::all(glm::lessThan(light, glm::dvec3(room.hi))));
    // Every room triangle faces the light (counter-clockwise seen from inside).
    for (size_t t = 0; t < world.triangles.size(); ++t) {
        const std::string& name = scene.instances[world.triangleInstance[t]].name;
        if (name.rfind("object-", 0) == 0) continue;
        const glm::dvec3 a(world.positions[world.triangles[t][0]]), b(world.positions[world.triangles[t][1]]),
            c(world.positions[world.triangles[t][2]]);
        CHECK(glm::dot(glm::cross(b - a, c - a), light - a) > 0.0);
    }
    // For each cube face (+x, -x, +y, -y, +z, -z), the object in that direction casts its
    // shadow's centre onto the room where the camera sees it.
    const char* faces[] = {"plus-x", "minus-x", "plus-y", "minus-y", "plus-z", "minus-z"};
    for (int face = 0; face < 6; ++face) {
        CAPTURE(faces[face]);
        const Box object = instanceBounds(scene, world, std::string("object-") + faces[face]);
        const glm::dvec3 direction = (glm::dvec3(object.lo) + glm::dvec3(object.hi)) * 0.5 - light;
        const int axis = face / 2;
        const double sign = face % 2 == 0 ? 1.0 : -1.0;
        for (int other = 0; other < 3; ++other)
            if (other != axis) CHECK(std::abs(direction[other]) < sign * direction[axis]);
        double exit = INFINITY;
        for (int a = 0; a < 3; ++a)
            exit = std::min(exit, ((direction[a] > 0 ? room.hi[a] : room.lo[a]) - light[a]) / direction[a]);
        CHECK(inFrustum(scene.camera, light + exit * direction));
    }
}

TEST_CASE("sun: sphere-box under a directional light from normalize(4, 8, 3)") {
    const Scene scene = loadHardCase("sun");
    REQUIRE(scene.lights.size() == 1);
    CHECK(scene.lights[0].type == LightType::Directional);
    CHECK(glm::length(glm::dvec3(scene.lights[0].direction) - glm::normalize(glm::dvec3(4, 8, 3))) < 1e-7);
    const Scene sphereBox = loadScene("sphere-box");
    CHECK(scene.instances.size() == sphereBox.instances.size());
    CHECK(flatten(scene).positions == flatten(sphereBox).positions);
}

TEST_CASE("spot: sphere-box under a 20 degree spot whose rim crosses the visible ground") {
    const Scene scene = loadHardCase("spot");
    REQUIRE(scene.lights.size() == 1);
    const Light& spot = scene.lights[0];
    CHECK(spot.type == LightType::Spot);
    CHECK(spot.coneAngleDeg == 20.0f);
    const auto degreesOffAxis = [&](glm::dvec3 p) {
        const glm::dvec3 axis = glm::normalize(glm::dvec3(spot.direction)), to = glm::normalize(p - glm::dvec3(spot.position));
        return glm::degrees(std::acos(glm::dot(axis, to)));
    };
    CHECK(degreesOffAxis({0.0, 0.0, 0.0}) < 1e-6);      // aimed at the sphere's foot
    CHECK(degreesOffAxis({0.0, 2.2, 0.0}) < 20.0);      // the sphere's top is lit
    CHECK(degreesOffAxis({-6.0, 0.0, 0.0}) > 20.0);     // ground outside the cone
    CHECK(inFrustum(scene.camera, glm::dvec3(-6.0, 0.0, 0.0)));      // ... that the camera sees
    CHECK(flatten(scene).positions == flatten(loadScene("sphere-box")).positions);
}
