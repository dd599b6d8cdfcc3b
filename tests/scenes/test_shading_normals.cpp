// Shading normals: angle-weighted vertex normals, the normals mesh files give, and how
// instances carry them into world space (scenes/shading_normals.h).
#include <cmath>
#include <stdexcept>

#include <doctest/doctest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "scenes/obj_reader.h"
#include "scenes/ply_reader.h"
#include "scenes/procedural.h"
#include "scenes/scene_error.h"
#include "scenes/shading_normals.h"

using namespace shadowlab;

namespace {

double angleDeg(const glm::dvec3& a, const glm::dvec3& b) {
    return glm::degrees(std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)));
}

// The box of makeBox with every quad cut along its other diagonal.
Mesh boxCutTheOtherWay() {
    Mesh mesh = makeBox(glm::vec3(-1.0f), glm::vec3(1.0f));
    mesh.cornerNormals.clear();
    for (size_t t = 0; t < mesh.triangles.size(); t += 2) {
        const uint32_t a = mesh.triangles[t][0], b = mesh.triangles[t][1], c = mesh.triangles[t][2],
                       d = mesh.triangles[t + 1][2];
        mesh.triangles[t] = {a, b, d};
        mesh.triangles[t + 1] = {b, c, d};
    }
    return mesh;
}

}  // namespace

TEST_CASE("angle-weighted normals do not depend on how a face is triangulated") {
    // At a box corner one face has one triangle and another two (halving the angle); uniform
    // or area weights (equal areas here) would tilt the normal towards the face with two.
    for (Mesh mesh : {makeBox(glm::vec3(-1.0f), glm::vec3(1.0f)), boxCutTheOtherWay()}) {
        mesh.cornerNormals.clear();
        const std::vector<glm::vec3> normals = angleWeightedNormals(mesh);
        REQUIRE(normals.size() == 8);
        for (size_t v = 0; v < 8; ++v) {
            CAPTURE(v);
            const glm::dvec3 expected = glm::normalize(glm::dvec3(mesh.positions[v]));
            CHECK(angleDeg(glm::dvec3(normals[v]), expected) < 1e-5);
        }
    }
}

TEST_CASE("corner normals: the mesh's own where given, angle-weighted where not, the face's for a lone vertex") {
    Mesh mesh = makeBox(glm::vec3(-1.0f), glm::vec3(1.0f));
    // A triangle of its own, far off, shares no vertex: its corners get its plane normal.
    const uint32_t base = uint32_t(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), {{5, 0, 0}, {6, 0, 0}, {5, 0, -1}});
    mesh.triangles.push_back({base, base + 1, base + 2});
    mesh.cornerNormals.resize(3 * mesh.triangles.size(), glm::vec3(0.0f));
    mesh.cornerNormals[0] = {0.0f, 0.0f, -3.0f};   // given, not unit: normalised
    mesh.cornerNormals[1] = glm::vec3(0.0f);       // a gap: the angle-weighted vertex normal

    const std::vector<glm::vec3> normals = cornerShadingNormals(mesh);
    REQUIRE(normals.size() == 3 * mesh.triangles.size());
    CHECK(normals[0] == glm::vec3(0.0f, 0.0f, -1.0f));
    const glm::dvec3 cornerDirection = glm::normalize(glm::dvec3(mesh.positions[mesh.triangles[0][1]]));
    CHECK(angleDeg(glm::dvec3(normals[1]), cornerDirection) < 1e-5);
    CHECK(normals[normals.size() - 1] == glm::vec3(0.0f, 1.0f, 0.0f));

    mesh.cornerNormals.pop_back();
    CHECK_THROWS_AS(cornerShadingNormals(mesh), std::invalid_argument);
    mesh.cornerNormals.push_back({NAN, 0.0f, 0.0f});
    CHECK_THROWS_AS(cornerShadingNormals(mesh), std::invalid_argument);
}

TEST_CASE("procedural meshes carry their exact normals") {
    const Mesh sphere = makeUvSphere(2.0f, 12, 7);
    REQUIRE(sphere.cornerNormals.size() == 3 * sphere.triangles.size());
    for (size_t t = 0; t < sphere.triangles.size(); ++t)
        for (int c = 0; c < 3; ++c)
            CHECK(angleDeg(glm::dvec3(sphere.cornerNormals[3 * t + c]), glm::dvec3(sphere.positions[sphere.triangles[t][c]])) < 1e-5);
    const Mesh box = makeBox(glm::vec3(0.0f), glm::vec3(1.0f, 2.0f, 3.0f));
    for (size_t t = 0; t < box.triangles.size(); ++t) {
        const glm::dvec3 p0(box.positions[box.triangles[t][0]]), p1(box.positions[box.triangles[t][1]]),
            p2(box.positions[box.triangles[t][2]]);
        for (int c = 0; c < 3; ++c) CHECK(glm::dvec3(box.cornerNormals[3 * t + c]) == glm::normalize(glm::cross(p1 - p0, p2 - p0)));
    }
    for (const glm::vec3& n : makeGrid({2.0f, 3.0f}, {2, 2}).cornerNormals) CHECK(n == glm::vec3(0.0f, 1.0f, 0.0f));
}

TEST_CASE("instances carry normals by the cofactor matrix: an ellipsoid's normals are its gradient") {
    Scene scene;
    scene.meshes.push_back(makeUvSphere(1.0f, 16, 9));
    scene.materials.push_back(Material{});
    MeshInstance instance;
    const glm::vec3 scale(3.0f, 1.0f, 0.5f);
    instance.worldFromObject = glm::translate(glm::mat4(1.0f), glm::vec3(1, 2, 3)) * glm::scale(glm::mat4(1.0f), scale);
    scene.instances.push_back(instance);
    const WorldGeometry world = flatten(scene);
    REQUIRE(world.cornerNormals.size() == 3 * world.triangles.size());
    // x^2/a^2 + y^2/b^2 + z^2/c^2 = 1 has gradient (x/a^2, y/b^2, z/c^2) at a world point
    // relative to the centre; the linear part alone would tilt it the other way.
    const glm::dvec3 s(scale);
    for (size_t t = 0; t < world.triangles.size(); ++t) {
        for (int c = 0; c < 3; ++c) {
            const glm::dvec3 p = glm::dvec3(world.positions[world.triangles[t][c]]) - glm::dvec3(1, 2, 3);
            CHECK(angleDeg(glm::dvec3(world.cornerNormals[3 * t + c]), p / (s * s)) < 1e-4);
        }
    }
}

TEST_CASE("OBJ corner normals: v//vn and v/vt/vn, gaps as 0, errors named") {
    const Mesh mesh = parseObj(
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
        "vn 0 0 2\nvn 0 1 0\nvt 0 0\n"
        "f 1//1 2//2 3//1 4//2\n"   // a quad: fans (1 2 3), (1 3 4)
        "f 1/1/2 3 4\n",            // only the first corner names a normal
        "normals.obj");
    REQUIRE(mesh.triangles.size() == 3);
    REQUIRE(mesh.cornerNormals.size() == 9);
    const glm::vec3 n1(0, 0, 2), n2(0, 1, 0), none(0.0f);
    const glm::vec3 expected[9] = {n1, n2, n1, n1, n1, n2, n2, none, none};
    for (int c = 0; c < 9; ++c) CHECK(mesh.cornerNormals[c] == expected[c]);
    CHECK(parseObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "plain.obj").cornerNormals.empty());

    CHECK_THROWS_WITH_AS(parseObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn nan 0 1\nf 1//1 2//1 3//1\n", "bad.obj"),
                         doctest::Contains("line 4: normal x \"nan\" is not a finite float"), SceneError);
    CHECK_THROWS_WITH_AS(parseObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//2 3//1\n", "bad.obj"),
                         doctest::Contains("normal index 2 (1-based) is out of range"), SceneError);
}

TEST_CASE("PLY vertex normals become corner normals, a partial set is an error") {
    const std::string header = "ply\nformat ascii 1.0\nelement vertex 4\n"
                               "property float x\nproperty float y\nproperty float z\n";
    const std::string faces = "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
    const Mesh mesh = parsePly(header + "property float nx\nproperty float ny\nproperty float nz\n" + faces +
                                   "0 0 0 0 0 1\n1 0 0 1 0 0\n1 1 0 0 1 0\n0 1 0 0 0 3\n4 0 1 2 3\n",
                               "normals.ply");
    REQUIRE(mesh.triangles.size() == 2);
    REQUIRE(mesh.cornerNormals.size() == 6);
    const glm::vec3 byVertex[4] = {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 3}};
    for (int t = 0; t < 2; ++t)
        for (int c = 0; c < 3; ++c) CHECK(mesh.cornerNormals[3 * t + c] == byVertex[mesh.triangles[t][c]]);

    CHECK_THROWS_WITH_AS(parsePly(header + "property float nx\n" + faces + "0 0 0 0\n1 0 0 0\n1 1 0 0\n0 1 0 0\n3 0 1 2\n",
                                  "partial.ply"),
                         doctest::Contains("some but not all of nx, ny, nz"), SceneError);
    CHECK_THROWS_WITH_AS(parsePly(header + "property float nx\nproperty float ny\nproperty float nz\n" + faces +
                                      "0 0 0 0 0 1\n1 0 0 1e39 0 0\n1 1 0 0 1 0\n0 1 0 0 0 1\n3 0 1 2\n",
                                  "inf.ply"),
                         doctest::Contains("normal (1e+39, 0, 0) is not finite as a float"), SceneError);
}
