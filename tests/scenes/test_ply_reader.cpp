// readPly on small ASCII and binary little-endian files written here.
#include <cmath>
#include <cstring>
#include <limits>

#include <doctest/doctest.h>

#include "scenes/ply_reader.h"
#include "tests/scenes/scene_test_files.h"

using namespace shadowlab;

namespace {

// Appends the bytes of each value as the (little-endian) machine stores them.
template <class... T>
void append(std::string& bytes, T... values) {
    (bytes.append(reinterpret_cast<const char*>(&values), sizeof values), ...);
}

const char* kAsciiSquarePlusTriangle =
    "ply\n"
    "format ascii 1.0\n"
    "comment a unit square as one quad, and a triangle, with extra properties\n"
    "element vertex 5\n"
    "property float x\nproperty float y\nproperty float z\nproperty uchar red\n"
    "element material 1\n"
    "property list uchar float weights\n"
    "element face 2\n"
    "property uchar flags\n"
    "property list uchar int vertex_indices\n"
    "end_header\n"
    "0 0 0 255\n1 0 0 0\n1 1 0 0\n0 1 0 0\n0.5 2 -0.25 7\n"
    "3 0.1 0.2 0.3\n"
    "0 4 0 1 2 3\n"
    "1 3 3 2 4\n";

// Header of a binary mesh: double x/y/z (with an int in between), int-counted
// "vertex_index" lists of uint indices.
std::string binaryHeader(int vertices, int faces) {
    return "ply\nformat binary_little_endian 1.0\n"
           "element vertex " + std::to_string(vertices) + "\n"
           "property double x\nproperty int id\nproperty double y\nproperty double z\n"
           "element face " + std::to_string(faces) + "\n"
           "property list int uint vertex_index\n"
           "end_header\n";
}

void appendVertex(std::string& bytes, double x, double y, double z) { append(bytes, x, int32_t(7), y, z); }

std::string binaryTriangle(double firstX) {
    std::string bytes = binaryHeader(3, 1);
    appendVertex(bytes, firstX, 0.0, 0.0);
    appendVertex(bytes, 1.0, 0.0, 0.0);
    appendVertex(bytes, 0.0, 1.0, 0.0);
    append(bytes, int32_t(3), uint32_t(0), uint32_t(1), uint32_t(2));
    return bytes;
}

}  // namespace

TEST_CASE("readPly ascii: positions, quads as fans, skipped properties and elements") {
    const test::TempDir dir;
    const Mesh mesh = readPly(dir.write("square.ply", kAsciiSquarePlusTriangle));
    REQUIRE(mesh.positions.size() == 5);
    CHECK(mesh.positions[4] == glm::vec3(0.5f, 2.0f, -0.25f));
    REQUIRE(mesh.triangles.size() == 3);
    CHECK(mesh.triangles[0] == glm::uvec3(0, 1, 2));
    CHECK(mesh.triangles[1] == glm::uvec3(0, 2, 3));
    CHECK(mesh.triangles[2] == glm::uvec3(3, 2, 4));
}

TEST_CASE("readPly binary little-endian: double positions, int counts, vertex_index") {
    const test::TempDir dir;
    std::string bytes = binaryHeader(4, 1);
    appendVertex(bytes, 0.1, 0.0, 0.0);
    appendVertex(bytes, 1.0, 0.0, 0.0);
    appendVertex(bytes, 1.0, 1.0, 1e-3);
    appendVertex(bytes, 0.0, 1.0, -2.5);
    append(bytes, int32_t(4), uint32_t(0), uint32_t(1), uint32_t(2), uint32_t(3));
    const Mesh mesh = readPly(dir.write("quad.ply", bytes));
    REQUIRE(mesh.positions.size() == 4);
    CHECK(mesh.positions[0].x == 0.1f);   // double rounded once to float
    CHECK(mesh.positions[2].z == 1e-3f);
    CHECK(mesh.positions[3] == glm::vec3(0.0f, 1.0f, -2.5f));
    REQUIRE(mesh.triangles.size() == 2);
    CHECK(mesh.triangles[1] == glm::uvec3(0, 2, 3));
}

TEST_CASE("readPly binary with float positions and uchar counts, as most tools write") {
    const test::TempDir dir;
    std::string bytes =
        "ply\nformat binary_little_endian 1.0\nelement vertex 3\n"
        "property float x\nproperty float y\nproperty float z\n"
        "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
    append(bytes, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f);
    append(bytes, uint8_t(3), int32_t(0), int32_t(1), int32_t(2));
    const Mesh mesh = readPly(dir.write("tri.ply", bytes));
    CHECK(mesh.positions.size() == 3);
    CHECK(mesh.triangles == std::vector<glm::uvec3>{{0, 1, 2}});
}

TEST_CASE("readPly: malformed files are SceneErrors naming the file and the row") {
    const test::TempDir dir;
    const std::string ascii = kAsciiSquarePlusTriangle;
    auto replaced = [&](const std::string& from, const std::string& to) {
        std::string text = ascii;
        text.replace(text.find(from), from.size(), to);
        return text;
    };
    const std::string valid = binaryTriangle(0.0);
    std::string twoCorners = binaryHeader(3, 1);
    for (int v = 0; v < 3; ++v) appendVertex(twoCorners, v, 1.0, 0.0);
    append(twoCorners, int32_t(2), uint32_t(0), uint32_t(1));
    struct Case {
        std::string bytes;
        std::vector<std::string> pieces;
    };
    const Case cases[] = {
        {valid.substr(0, valid.size() - 3), {"element face 0", "truncated"}},
        {valid.substr(0, valid.size() - 40), {"element vertex 2", "truncated"}},
        {binaryTriangle(std::numeric_limits<double>::quiet_NaN()), {"element vertex 0", "not finite"}},
        {binaryTriangle(1e300), {"element vertex 0", "not finite"}},
        {twoCorners, {"element face 0", "at least 3 vertices"}},
        {replaced("1 3 3 2 4", "1 3 3 2 5"), {"element face 1", "vertex index 5 is out of range", "5 vertices"}},
        {replaced("1 3 3 2 4", "1 3 3 2 -1"), {"element face 1", "vertex index -1 is out of range"}},
        {replaced("1 3 3 2 4", "1 -3 3 2 4"), {"element face 1", "line 22", "\"-3\" is not a valid uchar"}},
        {replaced("0.5 2 -0.25 7", "0.5 nan -0.25 7"), {"element vertex 4", "not finite"}},
        {replaced("0.5 2 -0.25 7", "0.5 two -0.25 7"), {"element vertex 4", "line 19", "\"two\""}},
        {replaced("0 1 0 0\n", "0 1 0 256\n"), {"element vertex 3", "\"256\" is not a valid uchar"}},
        {replaced("1 3 3 2 4\n", ""), {"element face 1", "unexpected end of file"}},
        {replaced("format ascii", "format binary_big_endian"), {"header line 2", "binary_big_endian"}},
        {ascii.substr(0, ascii.find("end_header")), {"the file ends before \"end_header\""}},
        {replaced("property float y", "property float64x y"), {"header line 6", "unknown property type \"float64x\""}},
        {replaced("vertex_indices", "corners"), {"no list property \"vertex_indices\""}},
        {replaced("property float z", "property float w"), {"no scalar property \"z\""}},
        {replaced("ply\n", "plyx\n"), {"not a PLY file"}},
        // Rows without properties consume nothing: this count made the reader loop forever.
        {replaced("element face 2", "element empty 18446744073709551615\nelement face 2"),
         {"element \"empty\" has 18446744073709551615 rows but no properties"}},
    };
    for (const Case& c : cases) {
        CAPTURE(c.pieces.front());
        const std::string path = dir.write("bad.ply", c.bytes);
        std::vector<std::string> pieces = c.pieces;
        pieces.push_back(path);
        test::checkMessage(test::sceneErrorOf([&] { readPly(path); }), pieces);
    }
}
