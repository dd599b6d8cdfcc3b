// flatten() and the instance transforms of the scene format.
#include <doctest/doctest.h>
#include <glm/glm.hpp>

#include "scenes/scene_file.h"
#include "tests/scenes/scene_test_files.h"

using namespace shadowlab;

namespace {

Mesh oneTriangle() {
    Mesh mesh;
    mesh.positions = {{0.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}};
    mesh.triangles = {{0, 1, 2}};
    return mesh;
}

// A scene file with one triangle mesh and one instance whose extra fields are given.
std::string sceneWithInstance(const std::string& instanceFields) {
    return R"({
      "meshes": [{"name": "tri", "file": "tri.obj"}],
      "materials": [{"name": "m"}],
      "instances": [{"mesh": "tri", "material": "m")" + instanceFields + R"(}],
      "lights": [{"type": "point", "position": [0, 5, 0], "power": 1}],
      "camera": {"eye": [0, 0, 5], "target": [0, 0, 0], "fovy": 45, "width": 64, "height": 64}
    })";
}

// World positions of the single instance of sceneWithInstance(instanceFields).
std::vector<glm::vec3> placed(const std::string& instanceFields) {
    const test::TempDir dir;
    dir.write("tri.obj", "v 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\n");
    return flatten(loadScene(dir.write("scene.json", sceneWithInstance(instanceFields)))).positions;
}

void checkNear(const glm::vec3& actual, const glm::vec3& expected) {
    CAPTURE(actual.x);
    CAPTURE(actual.y);
    CAPTURE(actual.z);
    CHECK(glm::length(actual - expected) < 1e-6f);
}

}  // namespace

TEST_CASE("flatten: world positions are worldFromObject * p, indices offset per instance") {
    Scene scene;
    scene.meshes = {oneTriangle()};
    scene.materials = {Material{}, Material{}};
    MeshInstance a{"a", 0, 1, glm::mat4(1.0f)};
    MeshInstance b{"b", 0, 0, glm::mat4(1.0f)};
    b.worldFromObject[0][0] = 2.0f;                                // scale x by 2
    b.worldFromObject[3] = glm::vec4(10.0f, 20.0f, 30.0f, 1.0f);  // then translate
    scene.instances = {a, b};

    const WorldGeometry world = flatten(scene);
    REQUIRE(world.positions.size() == 6);
    REQUIRE(world.triangles.size() == 2);
    CHECK(world.positions[1] == glm::vec3(1.0f, 0.0f, 0.0f));
    CHECK(world.positions[3] == glm::vec3(10.0f, 20.0f, 30.0f));
    CHECK(world.positions[4] == glm::vec3(12.0f, 20.0f, 30.0f));
    CHECK(world.positions[5] == glm::vec3(10.0f, 21.0f, 30.0f));
    CHECK(world.triangles[0] == glm::uvec3(0, 1, 2));
    CHECK(world.triangles[1] == glm::uvec3(3, 4, 5));
    CHECK(world.triangleMaterial == std::vector<uint32_t>{1, 0});
    CHECK(world.triangleInstance == std::vector<uint32_t>{0, 1});
}

TEST_CASE("instance transforms: scale, then rotate x, y, z, then translate") {
    SUBCASE("translate") {
        checkNear(placed(R"(, "translate": [1, 2, 3])")[0], {2.0f, 2.0f, 3.0f});
    }
    SUBCASE("uniform and per-axis scale") {
        checkNear(placed(R"(, "scale": 2)")[1], {0.0f, 2.0f, 0.0f});
        checkNear(placed(R"(, "scale": [1, 3, 1])")[1], {0.0f, 3.0f, 0.0f});
    }
    SUBCASE("rotate about y by 90 degrees is counter-clockwise seen from +Y: x goes to -z") {
        checkNear(placed(R"(, "rotate": [0, 90, 0])")[0], {0.0f, 0.0f, -1.0f});
    }
    SUBCASE("x first, then y: (0,1,0) -x90-> (0,0,1) -y90-> (1,0,0)") {
        checkNear(placed(R"(, "rotate": [90, 90, 0])")[1], {1.0f, 0.0f, 0.0f});
    }
    SUBCASE("scale before translate") {
        checkNear(placed(R"(, "scale": 2, "translate": [1, 0, 0])")[0], {3.0f, 0.0f, 0.0f});
    }
    SUBCASE("matrix is row-major: the translation is the last column") {
        const auto p = placed(R"(, "matrix": [2, 0, 0, 5,  0, 1, 0, 6,  0, 0, 1, 7,  0, 0, 0, 1])");
        CHECK(p[0] == glm::vec3(7.0f, 6.0f, 7.0f));
        CHECK(p[2] == glm::vec3(5.0f, 6.0f, 8.0f));
    }
    SUBCASE("fit: height 2 and ground put the mesh on y = 0, 2 tall, before the transform") {
        const auto p = placed(R"(, "fit": {"height": 2, "ground": true}, "translate": [0, 1, 0])");
        CHECK(p[0] == glm::vec3(2.0f, 1.0f, 0.0f));
        CHECK(p[1] == glm::vec3(0.0f, 3.0f, 0.0f));
        CHECK(p[2] == glm::vec3(0.0f, 1.0f, 2.0f));
    }
}

TEST_CASE("repeat: copies on a lattice, x fastest, shifted in world space") {
    const test::TempDir dir;
    dir.write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const Scene scene = loadScene(dir.write(
        "scene.json", sceneWithInstance(R"(, "name": "t", "translate": [0, 0, 1],
                                             "repeat": {"count": [2, 1, 3], "offset": [10, 0, 100]})")));
    REQUIRE(scene.instances.size() == 6);
    CHECK(scene.instances[0].name == "t[0]");
    CHECK(scene.instances[5].name == "t[5]");
    const WorldGeometry world = flatten(scene);
    CHECK(world.positions[0 * 3] == glm::vec3(0.0f, 0.0f, 1.0f));
    CHECK(world.positions[1 * 3] == glm::vec3(10.0f, 0.0f, 1.0f));
    CHECK(world.positions[2 * 3] == glm::vec3(0.0f, 0.0f, 101.0f));
    CHECK(world.positions[5 * 3] == glm::vec3(10.0f, 0.0f, 201.0f));
}
