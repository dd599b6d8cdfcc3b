// The built-in scenes load with exactly the geometry, light and camera they promise.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>

#include <doctest/doctest.h>
#include <glm/glm.hpp>

#include "scenes/scene_file.h"
#include "tests/scenes/scene_test_files.h"

using namespace shadowlab;

namespace {

constexpr size_t kGroundTriangles = 64 * 64 * 2;

size_t triangleCount(const Scene& scene) {
    size_t count = 0;
    for (const MeshInstance& instance : scene.instances) count += scene.meshes[instance.mesh].triangles.size();
    return count;
}

// Lowest and highest world y over the instances whose name starts with prefix.
std::pair<float, float> worldYRange(const Scene& scene, const WorldGeometry& world, const std::string& prefix) {
    float lo = INFINITY, hi = -INFINITY;
    for (size_t t = 0; t < world.triangles.size(); ++t) {
        if (scene.instances[world.triangleInstance[t]].name.rfind(prefix, 0) != 0) continue;
        for (int c = 0; c < 3; ++c) {
            const float y = world.positions[world.triangles[t][c]].y;
            lo = std::min(lo, y);
            hi = std::max(hi, y);
        }
    }
    return {lo, hi};
}

// The disk light every built-in scene shares: centre (4,8,3), facing the origin.
void checkSharedLight(const Scene& scene) {
    REQUIRE(scene.lights.size() == 1);
    const Light& light = scene.lights[0];
    CHECK(light.type == LightType::Disk);
    CHECK(light.position == glm::vec3(4.0f, 8.0f, 3.0f));
    CHECK(light.radius == 0.5f);
    const glm::dvec3 expected = glm::normalize(glm::dvec3(-4.0, -8.0, -3.0));
    CHECK(glm::length(glm::dvec3(light.direction) - expected) < 1e-7);
    CHECK(light.intensity == glm::vec3(400.0f));
}

}  // namespace

TEST_CASE("builtinSceneNames lists the scene files by stem") {
    const std::vector<std::string> names = builtinSceneNames();
    for (const char* name : {"bunny", "sphere-box", "throughput"})
        CHECK(std::find(names.begin(), names.end(), name) != names.end());
    CHECK(std::is_sorted(names.begin(), names.end()));
}

TEST_CASE("sphere-box: ground 64x64, sphere 64x32, box, disk light, camera") {
    const Scene scene = loadScene("sphere-box");
    CHECK(scene.name == "sphere-box");
    REQUIRE(scene.instances.size() == 3);
    CHECK(triangleCount(scene) == kGroundTriangles + 64 * 31 * 2 + 12);
    checkSharedLight(scene);
    CHECK(scene.camera.eye == glm::vec3(0.0f, 4.0f, 9.0f));
    CHECK(scene.camera.target == glm::vec3(0.0f, 0.5f, 0.0f));
    CHECK(scene.camera.fovyDeg == 45.0f);
    CHECK(scene.camera.width == 1280);
    CHECK(scene.camera.height == 800);

    const WorldGeometry world = flatten(scene);
    const auto [sphereLo, sphereHi] = worldYRange(scene, world, "sphere");
    CHECK(sphereLo == -1.0f + 1.2f);   // pole + translation, rounded as float
    CHECK(sphereHi == 1.0f + 1.2f);
    const auto [boxLo, boxHi] = worldYRange(scene, world, "box");
    CHECK(boxLo == 0.0f);
    CHECK(boxHi == 1.5f);
}

TEST_CASE("bunny: 75,408 triangles scaled to height 2 with its lowest point on y = 0") {
    const Scene scene = loadScene("bunny");
    CHECK(triangleCount(scene) == kGroundTriangles + 75408);
    checkSharedLight(scene);
    const WorldGeometry world = flatten(scene);
    const auto [lo, hi] = worldYRange(scene, world, "bunny");
    CHECK(lo == 0.0f);
    CHECK(hi == doctest::Approx(2.0).epsilon(1e-6));
}

TEST_CASE("throughput: 256 spheres of 128x64 sharing one mesh, resting on the ground") {
    const auto start = std::chrono::steady_clock::now();
    const Scene scene = loadScene("throughput");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    MESSAGE("loading throughput took ", seconds, " s");
    CHECK(scene.meshes.size() == 2);
    CHECK(scene.instances.size() == 1 + 256);
    CHECK(triangleCount(scene) == kGroundTriangles + 256 * 128 * 63 * 2);
    checkSharedLight(scene);
    CHECK(scene.camera.eye == glm::vec3(0.0f, 10.0f, 14.0f));

    const WorldGeometry world = flatten(scene);
    CHECK(world.triangles.size() == 4136960);
    const auto [lo, hi] = worldYRange(scene, world, "sphere");
    CHECK(lo == 0.0f);
    CHECK(hi == 0.8f);
    // The lattice is centred: first and last sphere centres at -7.5 and +7.5.
    CHECK(glm::vec3(scene.instances[1].worldFromObject[3]) == glm::vec3(-7.5f, 0.4f, -7.5f));
    CHECK(glm::vec3(scene.instances[256].worldFromObject[3]) == glm::vec3(7.5f, 0.4f, 7.5f));
}

// Sets an environment variable for the lifetime of the object.
struct ScopedEnv {
    ScopedEnv(const char* name, const std::string& value) : name(name) { setenv(name, value.c_str(), 1); }
    ~ScopedEnv() { unsetenv(name); }
    const char* name;
};

TEST_CASE("SHADOWLAB_SCENE_DIR overrides the built-in scene directory") {
    const test::TempDir dir;
    std::ifstream original(builtinSceneDir() + "/sphere-box.json");
    dir.write("copy-of-sphere-box.json", std::string(std::istreambuf_iterator<char>(original), {}));
    const ScopedEnv env("SHADOWLAB_SCENE_DIR", dir.path(""));
    CHECK(builtinSceneNames() == std::vector<std::string>{"copy-of-sphere-box"});
    CHECK(loadScene("copy-of-sphere-box").instances.size() == 3);
    test::checkMessage(test::sceneErrorOf([] { loadScene("no-such-scene"); }),
                       {"unknown scene \"no-such-scene\"", "copy-of-sphere-box"});
}

TEST_CASE("the built-in scenes are scenes/ of the data folder, which SHADOWLAB_SCENE_DIR does not move") {
    // The test program is not installed, so the folder is the one it was compiled with.
    CHECK(builtinDataDir() == std::string(SHADOWLAB_DATA_DIR));
    CHECK(builtinSceneDir() == builtinDataDir() + "/scenes");
    CHECK(std::filesystem::is_regular_file(builtinDataDir() + "/meshes/bunny.obj"));
    const test::TempDir dir;
    const ScopedEnv env("SHADOWLAB_SCENE_DIR", dir.path(""));
    CHECK(builtinSceneDir() == dir.path(""));
    CHECK(builtinDataDir() == std::string(SHADOWLAB_DATA_DIR));
}
