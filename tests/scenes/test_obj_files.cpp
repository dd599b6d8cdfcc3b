// OBJ export (writeObj) and import (readObj).
#include <cstring>
#include <filesystem>

#include <doctest/doctest.h>
#include <tiny_obj_loader.h>

#include "scenes/obj_reader.h"
#include "scenes/obj_writer.h"
#include "scenes/scene_file.h"
#include "tests/scenes/scene_test_files.h"

using namespace shadowlab;

TEST_CASE("writeObj: read back by tinyobjloader, every float bit for bit") {
    const test::TempDir dir;
    WorldGeometry world = flatten(loadScene("sphere-box"));
    // Values whose shortest decimal needs all 9 digits, and extremes of the float range.
    world.positions.push_back({0.1f, 1.0f / 3.0f, std::nextafter(1.0f, 2.0f)});
    world.positions.push_back({-3.4028235e38f, 1.17549435e-38f, 1.4e-45f});
    world.triangles.push_back({uint32_t(world.positions.size()) - 2, uint32_t(world.positions.size()) - 1, 0});
    const std::string path = dir.path("out.obj");
    writeObj(world, path);

    tinyobj::ObjReader reader;
    tinyobj::ObjReaderConfig config;
    config.triangulate = false;
    REQUIRE(reader.ParseFromFile(path, config));
    const std::vector<tinyobj::real_t>& xyz = reader.GetAttrib().vertices;
    REQUIRE(xyz.size() == world.positions.size() * 3);
    CHECK(std::memcmp(xyz.data(), world.positions.data(), xyz.size() * sizeof(float)) == 0);
    const tinyobj::mesh_t& mesh = reader.GetShapes().at(0).mesh;
    REQUIRE(mesh.indices.size() == world.triangles.size() * 3);
    for (size_t t = 0; t < world.triangles.size(); ++t)
        for (int c = 0; c < 3; ++c) REQUIRE(mesh.indices[t * 3 + c].vertex_index == int(world.triangles[t][c]));
    CHECK_FALSE(std::filesystem::exists(path + ".partial"));
}

TEST_CASE("writeObj: a failed write leaves no file and names it") {
    const test::TempDir dir;
    const std::string path = dir.path("missing-directory/out.obj");
    WorldGeometry world;
    world.positions = {{0, 0, 0}};
    try {
        writeObj(world, path);
        FAIL("expected an error");
    } catch (const std::runtime_error& error) {
        CHECK(std::string(error.what()).find("missing-directory/out.obj") != std::string::npos);
    }
    CHECK_FALSE(std::filesystem::exists(path));
}

TEST_CASE("readObj: polygons as fans, groups, negative indices, ignored attributes") {
    const test::TempDir dir;
    const std::string path = dir.write("shapes.obj",
        "# a quad and a pentagon in two groups\n"
        "mtllib none.mtl\n"
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
        "vn 0 0 1\nvt 0 0\n"
        "g quad\nusemtl red\nf 1//1 2//1 3//1 4//1\n"
        "v 5 0 0\nv 6 0 0\nv 6 1 0\nv 5.5 2 0\nv 5 1 0\n"
        "g pentagon\nf -5/1 -4/1 -3/1 -2/1 -1/1\n"
        "l 1 2\n");
    const Mesh mesh = readObj(path);
    CHECK(mesh.positions.size() == 9);
    CHECK(mesh.positions[7] == glm::vec3(5.5f, 2.0f, 0.0f));
    REQUIRE(mesh.triangles.size() == 2 + 3);
    CHECK(mesh.triangles[0] == glm::uvec3(0, 1, 2));
    CHECK(mesh.triangles[1] == glm::uvec3(0, 2, 3));
    CHECK(mesh.triangles[2] == glm::uvec3(4, 5, 6));
    CHECK(mesh.triangles[4] == glm::uvec3(4, 7, 8));
    // The quad names no texture coordinate, the pentagon "vt 0 0" at every corner.
    REQUIRE(mesh.cornerUvs.size() == 3 * mesh.triangles.size());
    CHECK(mesh.cornerUvs[0] == glm::vec2(0.0f));
}

TEST_CASE("readObj: texture coordinates per corner, for cut-outs") {
    const test::TempDir dir;
    const Mesh mesh = readObj(dir.write("card.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                                    "vt 0 0\nvt 1 0\nvt 1 1 0.5\nvt 0 1\n"
                                                    "f 1/1 2/2 3/3 4/4\n"));
    REQUIRE(mesh.cornerUvs.size() == 6);
    CHECK(mesh.cornerUvs[1] == glm::vec2(1.0f, 0.0f));
    CHECK(mesh.cornerUvs[2] == glm::vec2(1.0f, 1.0f));   // the w of "vt 1 1 0.5" is not read
    CHECK(mesh.cornerUvs[5] == glm::vec2(0.0f, 1.0f));
    CHECK(readObj(dir.write("plain.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")).cornerUvs.empty());
}

TEST_CASE("readObj: malformed files are SceneErrors naming the file and the place") {
    const test::TempDir dir;
    struct Case {
        const char* text;
        std::vector<std::string> pieces;
    };
    const Case cases[] = {
        {"v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n", {"line 2", "vertex x \"nan\" is not a finite float"}},
        {"v 0 0 0\nv 1 0 inf\nv 0 1 0\nf 1 2 3\n", {"line 2", "vertex z \"inf\""}},
        {"v 0 0 0\nv 1 0 1e39\nv 0 1 0\nf 1 2 3\n", {"line 2", "vertex z \"1e39\""}},
        {"v 0 0 0\nv 1 0\nv 0 1 0\nf 1 2 3\n", {"line 2", "vertex has no z"}},
        {"v 0 0 0\nv 1,5 0 0\nv 0 1 0\nf 1 2 3\n", {"line 2", "vertex x \"1,5\""}},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 9\n", {"face 1", "vertex index 9", "out of range", "3 vertices"}},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n", {"face 0", "vertex index 0", "out of range"}},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2\n", {"1 face(s) with fewer than 3 vertices"}},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", {"line 4"}},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 nan\nf 1/1 2/1 3/1\n", {"line 4", "texture coordinate v \"nan\""}},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0\nf 1/1 2/1 3/1\n", {"line 4", "texture coordinate has no v"}},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/2 3/1\n", {"face 0", "texture coordinate index 2", "out of range"}},
    };
    for (const Case& c : cases) {
        CAPTURE(c.text);
        const std::string path = dir.write("bad.obj", c.text);
        std::vector<std::string> pieces = c.pieces;
        pieces.push_back(path);
        test::checkMessage(test::sceneErrorOf([&] { readObj(path); }), pieces);
    }
    test::checkMessage(test::sceneErrorOf([&] { readObj(dir.path("absent.obj")); }),
                       {dir.path("absent.obj"), "cannot open"});
}
