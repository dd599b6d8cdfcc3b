// Procedural meshes: exact counts, exact positions, outward counter-clockwise faces,
// no degenerate triangles and, for the closed ones, every edge shared by two faces.
#include <cmath>
#include <map>
#include <utility>

#include <doctest/doctest.h>
#include <glm/glm.hpp>

#include "scenes/procedural.h"

using namespace shadowlab;

namespace {

glm::dvec3 corner(const Mesh& mesh, uint32_t index) { return glm::dvec3(mesh.positions[index]); }

// Twice the area vector of a triangle, in double: its direction is the CCW normal.
glm::dvec3 areaVector(const Mesh& mesh, const glm::uvec3& t) {
    return glm::cross(corner(mesh, t.y) - corner(mesh, t.x), corner(mesh, t.z) - corner(mesh, t.x));
}

glm::dvec3 centroid(const Mesh& mesh, const glm::uvec3& t) {
    return (corner(mesh, t.x) + corner(mesh, t.y) + corner(mesh, t.z)) / 3.0;
}

// Closed and consistently oriented: each directed edge once, and its reverse once.
void checkClosedOriented(const Mesh& mesh) {
    std::map<std::pair<uint32_t, uint32_t>, int> directedEdges;
    for (const glm::uvec3& t : mesh.triangles) {
        ++directedEdges[{t.x, t.y}];
        ++directedEdges[{t.y, t.z}];
        ++directedEdges[{t.z, t.x}];
    }
    for (const auto& [edge, count] : directedEdges) {
        REQUIRE(count == 1);
        REQUIRE(directedEdges.count({edge.second, edge.first}) == 1);
    }
}

// Every face's CCW normal points away from the centre (the origin for these meshes).
void checkOutward(const Mesh& mesh, glm::dvec3 centre) {
    for (const glm::uvec3& t : mesh.triangles) {
        const glm::dvec3 n = areaVector(mesh, t);
        REQUIRE(glm::length(n) > 0.0);
        REQUIRE(glm::dot(n, centroid(mesh, t) - centre) > 0.0);
    }
}

}  // namespace

TEST_CASE("grid: counts, exact corners, faces +Y") {
    const Mesh grid = makeGrid({20.0f, 10.0f}, {64, 32});
    CHECK(grid.positions.size() == 65u * 33u);
    CHECK(grid.triangles.size() == 64u * 32u * 2u);
    CHECK(grid.triangles.size() == gridTriangleCount({64, 32}));   // the count the loader checks limits by
    CHECK(grid.positions.front() == glm::vec3(-10.0f, 0.0f, -5.0f));
    CHECK(grid.positions.back() == glm::vec3(10.0f, 0.0f, 5.0f));
    CHECK(grid.positions[32] == glm::vec3(0.0f, 0.0f, -5.0f));   // the middle column is exactly x = 0
    for (const glm::uvec3& t : grid.triangles) {
        const glm::dvec3 n = areaVector(grid, t);
        REQUIRE(n.y > 0.0);
        REQUIRE(n.x == 0.0);
        REQUIRE(n.z == 0.0);
    }
}

TEST_CASE("uv-sphere: slices*(stacks-1)*2 triangles, radius to one ulp, outward, closed") {
    for (const std::pair<int, int>& size : {std::pair{3, 2}, std::pair{64, 32}, std::pair{128, 64}, std::pair{7, 5}}) {
        const int slices = size.first, stacks = size.second;   // named, not bound: CAPTURE takes them by reference
        CAPTURE(slices);
        CAPTURE(stacks);
        const float radius = 0.4f;
        const Mesh sphere = makeUvSphere(radius, slices, stacks);
        CHECK(sphere.triangles.size() == size_t(slices) * size_t(stacks - 1) * 2);
        CHECK(sphere.triangles.size() == uvSphereTriangleCount(slices, stacks));
        CHECK(sphere.positions.size() == size_t(slices) * size_t(stacks - 1) + 2);
        CHECK(sphere.positions.front() == glm::vec3(0.0f, radius, 0.0f));
        CHECK(sphere.positions.back() == glm::vec3(0.0f, -radius, 0.0f));
        // Each coordinate is rounded once from double, so the length is off by < 1 ulp(r).
        const double ulp = std::nextafter(radius, 1.0f) - radius;
        for (const glm::vec3& p : sphere.positions) REQUIRE(std::abs(glm::length(glm::dvec3(p)) - radius) < ulp);
        checkOutward(sphere, glm::dvec3(0.0));
        checkClosedOriented(sphere);
    }
}

TEST_CASE("box: 8 exact corners, 12 outward triangles, closed") {
    const Mesh box = makeBox({1.5f, 0.0f, -1.5f}, {2.5f, 1.5f, -0.5f});
    CHECK(box.positions.size() == 8);
    CHECK(box.triangles.size() == 12);
    for (const glm::vec3& p : box.positions) {
        CHECK((p.x == 1.5f || p.x == 2.5f));
        CHECK((p.y == 0.0f || p.y == 1.5f));
        CHECK((p.z == -1.5f || p.z == -0.5f));
    }
    checkOutward(box, glm::dvec3(2.0, 0.75, -1.0));
    checkClosedOriented(box);
}
