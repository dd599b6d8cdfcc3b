// Caster level of detail (scenes/caster_lod.h): the simplified meshes keep the share of
// triangles asked for, only vertices they had and their shape within a stated distance;
// open borders stay put, closed meshes stay closed; each ratio is built once.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>
#include <tuple>

#include <glm/gtc/matrix_transform.hpp>

#include "scenes/caster_lod.h"
#include "scenes/edge_adjacency.h"
#include "scenes/procedural.h"
#include "scenes/scene_file.h"

using namespace shadowlab;

namespace {

std::tuple<float, float, float> key(const glm::vec3& p) { return {p.x, p.y, p.z}; }

// Distance from p to the triangle abc (Ericson, Real-Time Collision Detection, 5.1.5),
// in double: the closest point by the region of the triangle it falls in.
double pointTriangleDistance(glm::dvec3 p, glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {
    const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return glm::length(p - a);
    const glm::dvec3 bp = p - b;
    const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return glm::length(p - b);
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return glm::length(p - (a + ab * (d1 / (d1 - d3))));
    const glm::dvec3 cp = p - c;
    const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return glm::length(p - c);
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return glm::length(p - (a + ac * (d2 / (d2 - d6))));
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) return glm::length(p - (b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)))));
    const double denom = 1.0 / (va + vb + vc);
    return glm::length(p - (a + ab * (vb * denom) + ac * (vc * denom)));
}

double distanceToMesh(const glm::vec3& p, const Mesh& mesh) {
    double nearest = std::numeric_limits<double>::max();
    for (const glm::uvec3& t : mesh.triangles)
        nearest = std::min(nearest, pointTriangleDistance(p, mesh.positions[t.x], mesh.positions[t.y], mesh.positions[t.z]));
    return nearest;
}

double area(const Mesh& mesh) {
    double sum = 0.0;
    for (const glm::uvec3& t : mesh.triangles) {
        const glm::dvec3 a = mesh.positions[t.x], b = mesh.positions[t.y], c = mesh.positions[t.z];
        sum += 0.5 * glm::length(glm::cross(b - a, c - a));
    }
    return sum;
}

Scene oneMeshScene(Mesh mesh, glm::mat4 worldFromObject = glm::mat4(1.0f)) {
    Scene scene;
    scene.meshes = {std::move(mesh)};
    scene.materials = {Material{}};
    scene.instances = {{"only", 0, 0, worldFromObject}};
    return scene;
}

}  // namespace

TEST_CASE("caster LOD: the bunny keeps a quarter of its triangles, only vertices it had, and its shape") {
    const Scene bunny = loadScene("bunny");
    const size_t m = std::distance(bunny.meshes.begin(), std::ranges::max_element(bunny.meshes, {}, [](const Mesh& x) {
                                       return x.triangles.size();
                                   }));
    const Mesh& full = bunny.meshes[m];
    const SimplifiedScene s = simplifyMeshes(oneMeshScene(full), 0.25);   // unscaled: errorM in the mesh's units
    const Mesh& simple = s.scene.meshes[0];
    const double n = double(full.triangles.size());
    CHECK(double(simple.triangles.size()) <= 0.25 * n + 1.0);
    CHECK(double(simple.triangles.size()) >= 0.2 * n);   // the simplifier reached (about) the target
    CHECK(simple.positions.size() < full.positions.size());
    CHECK(simple.cornerNormals.empty());
    // Edge collapses move no vertex: every kept one is one of the mesh's own, bit for bit.
    std::set<std::tuple<float, float, float>> original;
    for (const glm::vec3& p : full.positions) original.insert(key(p));
    CHECK(std::ranges::all_of(simple.positions, [&](const glm::vec3& p) { return original.contains(key(p)); }));
    CHECK(std::ranges::all_of(simple.triangles, [&](const glm::uvec3& t) { return std::max({t.x, t.y, t.z}) < simple.positions.size(); }));

    // The shape: every 97th original vertex lies within 0.2% of the bunny's size of the
    // simplified surface, and within twice the simplifier's own estimate (measured: 0.04%,
    // 1.3 times the estimate).
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const glm::vec3& p : full.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    const double size = glm::length(glm::dvec3(hi - lo));
    double farthest = 0.0;
    for (size_t v = 0; v < full.positions.size(); v += 97) farthest = std::max(farthest, distanceToMesh(full.positions[v], simple));
    CHECK(farthest < 0.002 * size);
    CHECK(s.errorM() < 0.002 * size);
    CHECK(farthest < 2.0 * s.errorM());
    // The rest of a scene is as it was: instances, materials, lights.
    const SimplifiedScene scene = simplifyMeshes(bunny, 0.25);
    CHECK(scene.scene.meshes[m].triangles == simple.triangles);
    CHECK(scene.scene.instances.size() == bunny.instances.size());
    CHECK(scene.scene.materials.size() == bunny.materials.size());
    CHECK(scene.scene.lights.size() == bunny.lights.size());
}

TEST_CASE("caster LOD: open borders stay where they were, so a ground keeps its outline and area") {
    const Mesh grid = makeGrid({20.0f, 20.0f}, {64, 64});
    const Mesh simple = simplifyMeshes(oneMeshScene(grid), 0.05).scene.meshes[0];
    CHECK(simple.triangles.size() < grid.triangles.size() / 10);
    CHECK(area(simple) == doctest::Approx(area(grid)).epsilon(1e-5));   // no fold, no hole
    CHECK(std::ranges::all_of(simple.positions, [](const glm::vec3& p) { return p.y == 0.0f; }));
    const EdgeAdjacency before = buildEdgeAdjacency(grid.positions, grid.triangles);
    const EdgeAdjacency after = buildEdgeAdjacency(simple.positions, simple.triangles);
    CHECK(after.openEdges == before.openEdges);   // the 4 x 64 border edges, every one kept
    // A quad cannot lose a triangle without losing its outline: it stays two.
    CHECK(simplifyMeshes(oneMeshScene(makeGrid({1.0f, 1.0f}, {1, 1})), 0.01).scene.meshes[0].triangles.size() == 2);
}

TEST_CASE("caster LOD: a closed sphere (split at its seam) stays closed, its vertices on the sphere") {
    const Mesh sphere = makeUvSphere(1.0f, 64, 32);
    const Mesh simple = simplifyMeshes(oneMeshScene(sphere), 0.05).scene.meshes[0];
    CHECK(simple.triangles.size() <= sphere.triangles.size() / 19);
    const EdgeAdjacency a = buildEdgeAdjacency(simple.positions, simple.triangles);
    CHECK(a.closed);
    CHECK(a.openEdges == 0);
    CHECK(a.nonManifoldEdges == 0);
    CHECK(std::ranges::all_of(simple.positions, [](const glm::vec3& p) { return std::abs(glm::length(p) - 1.0f) < 1e-5f; }));
}

TEST_CASE("caster LOD: no mesh falls below a tetrahedron, so no caster vanishes") {
    for (const Mesh& mesh : {makeBox(glm::vec3(0.0f), glm::vec3(1.0f)), makeUvSphere(1.0f, 64, 32)}) {
        INFO(mesh.source);
        const Mesh simple = simplifyMeshes(oneMeshScene(mesh), 0.001).scene.meshes[0];
        CHECK(simple.triangles.size() == 4);
        CHECK(simple.positions.size() == 4);
        CHECK(buildEdgeAdjacency(simple.positions, simple.triangles).closed);
    }
    const Mesh two = makeGrid({1.0f, 1.0f}, {1, 1});   // fewer than 4: kept whole
    CHECK(simplifyMeshes(oneMeshScene(two), 0.001).scene.meshes[0].triangles == two.triangles);
}

TEST_CASE("caster LOD: the error is in world metres, scaled with the instance, and the same every run") {
    const Mesh sphere = makeUvSphere(1.0f, 32, 16);
    const SimplifiedScene unit = simplifyMeshes(oneMeshScene(sphere), 0.1);
    const SimplifiedScene doubled = simplifyMeshes(oneMeshScene(sphere, glm::scale(glm::mat4(1.0f), glm::vec3(2.0f))), 0.1);
    CHECK(unit.errorM() > 0.0);
    CHECK(doubled.errorM() == doctest::Approx(2.0 * unit.errorM()));
    REQUIRE(unit.instanceErrorM.size() == 1);
    CHECK(double(unit.instanceErrorM[0]) == doctest::Approx(unit.errorM()));
    // Per instance: the same sphere whole beside a simplified one shares the mesh, so both
    // get its error, each at its own scale; a flat grid loses no shape and gets 0.
    Scene two = oneMeshScene(sphere);
    two.meshes.push_back(makeGrid({4.0f, 4.0f}, {16, 16}));
    two.instances.push_back({"scaled", 0, 0, glm::scale(glm::mat4(1.0f), glm::vec3(3.0f))});
    two.instances.push_back({"ground", 1, 0, glm::mat4(1.0f)});
    const SimplifiedScene both = simplifyMeshes(two, 0.1);
    REQUIRE(both.instanceErrorM.size() == 3);
    CHECK(double(both.instanceErrorM[1]) == doctest::Approx(3.0 * both.instanceErrorM[0]));
    CHECK(both.instanceErrorM[2] == 0.0f);
    CHECK(both.errorM() == doctest::Approx(both.instanceErrorM[1]));
    const SimplifiedScene again = simplifyMeshes(oneMeshScene(sphere), 0.1);
    CHECK(again.scene.meshes[0].positions == unit.scene.meshes[0].positions);
    CHECK(again.scene.meshes[0].triangles == unit.scene.meshes[0].triangles);
}

TEST_CASE("caster LOD: ratio 1 is the prepared scene itself, and each other ratio is built once") {
    const PreparedScene prepared(oneMeshScene(makeUvSphere(1.0f, 32, 16)));
    std::optional<double> ms;
    CHECK(&casterLevel(prepared, 1.0, &ms).casters == &prepared);
    CHECK_FALSE(ms);
    const PreparedScene* half = &casterLevel(prepared, 0.5, &ms).casters;
    CHECK(ms);
    CHECK(half != &prepared);
    CHECK(half->world().triangles.size() <= prepared.world().triangles.size() / 2);
    CHECK(&casterLevel(prepared, 0.5, &ms).casters == half);
    CHECK_FALSE(ms);   // kept, not rebuilt
    CHECK(&casterLevel(prepared, 0.25).casters != half);
    for (double bad : {0.0, -0.5, 1.5, std::nan("")}) {
        INFO(bad);
        CHECK_THROWS_AS(casterLevel(prepared, bad), std::invalid_argument);
        CHECK_THROWS_AS(simplifyMeshes(prepared.scene(), bad), std::invalid_argument);
    }
}
