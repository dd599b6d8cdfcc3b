// Edge adjacency (scenes/edge_adjacency.h), built once per prepared scene
// (scenes/prepared_scene.h): welding, open and non-manifold edges, and the build reported once.
#include <doctest/doctest.h>

#include <stdexcept>

#include "scenes/edge_adjacency.h"
#include "scenes/prepared_scene.h"
#include "scenes/procedural.h"
#include "tests/scenes/unwelded_mesh.h"

using namespace shadowlab;
using test::unwelded;

TEST_CASE("edge adjacency welds duplicated vertices and finds a cube closed") {
    const Mesh cube = makeBox(glm::vec3(0.0f), glm::vec3(1.0f));
    for (const Mesh& mesh : {cube, unwelded(cube)}) {
        const EdgeAdjacency a = buildEdgeAdjacency(mesh.positions, mesh.triangles);
        CHECK(a.edges.size() == 18);   // 12 cube edges and 6 face diagonals
        CHECK(a.uses.size() == 36);
        CHECK(a.closed);
        CHECK(a.openEdges == 0);
        CHECK(a.nonManifoldEdges == 0);
    }
    // A quad (diagonal 0-2) with a fin on its edge 0-1: open, still manifold; a second fin
    // on the same edge gives it three triangles.
    Mesh fin;
    fin.positions = {{0, 0, 0}, {1, 0, 0}, {1, 0, -1}, {0, 0, -1}, {0.5f, 1, 0}, {0.5f, -1, 0}};
    fin.triangles = {{0, 1, 2}, {0, 2, 3}, {1, 0, 4}};
    const EdgeAdjacency one = buildEdgeAdjacency(fin.positions, fin.triangles);
    CHECK_FALSE(one.closed);
    CHECK(one.openEdges == 5);   // the quad's other three edges and the fin's two
    CHECK(one.nonManifoldEdges == 0);
    fin.triangles.emplace_back(0, 1, 5);
    CHECK(buildEdgeAdjacency(fin.positions, fin.triangles).nonManifoldEdges == 1);
}

TEST_CASE("prepared scene: the edge adjacency is built once, on first use, and reported once") {
    Scene scene;
    scene.meshes = {makeBox(glm::vec3(0.0f), glm::vec3(1.0f))};
    scene.instances = {{"box", 0, 0, glm::mat4(1.0f)}};
    const PreparedScene prepared(scene);
    const std::optional<double> built = prepared.buildEdgeAdjacency();   // nothing built before
    REQUIRE(built.has_value());
    CHECK(*built >= 0.0);
    CHECK_FALSE(prepared.buildEdgeAdjacency().has_value());   // built, and reported, once
    const std::vector<EdgeAdjacency>* first = &prepared.edgeAdjacency();
    CHECK(&prepared.edgeAdjacency() == first);                 // the same data, not rebuilt
    CHECK((*first)[0].closed);
    // An edited copy is another prepared scene with its own edges: without one triangle
    // the box is open.
    scene.meshes[0].triangles.pop_back();
    scene.meshes[0].cornerNormals.resize(3 * scene.meshes[0].triangles.size());
    const PreparedScene edited(scene);
    CHECK_FALSE(edited.edgeAdjacency()[0].closed);
    CHECK(edited.edgeAdjacency()[0].edges.size() ==
          buildEdgeAdjacency(scene.meshes[0].positions, scene.meshes[0].triangles).edges.size());
    CHECK(prepared.edgeAdjacency()[0].closed);
}

namespace {

// Types for PreparedScene::derived (at namespace scope: a local class has no static members).
struct DerivedCount {
    static constexpr DependsOn kDependsOn = DependsOn::FixedContent;
    int value;
};
struct DerivedDoubled {
    static constexpr DependsOn kDependsOn = DependsOn::FixedContent;
    int value;
};
struct DerivedFailing {
    static constexpr DependsOn kDependsOn = DependsOn::FixedContent;
    int value;
};

}  // namespace

TEST_CASE("prepared scene: derived data is built once per type, reported once, rebuilt after a throw, and may derive another type") {
    Scene scene;
    scene.meshes = {makeBox(glm::vec3(0.0f), glm::vec3(1.0f))};
    scene.instances = {{"box", 0, 0, glm::mat4(1.0f)}};
    const PreparedScene prepared(scene);
    int builds = 0;
    std::optional<double> ms;
    CHECK(prepared.derived<DerivedCount>([&] { return DerivedCount{++builds}; }, &ms).value == 1);
    CHECK(ms.has_value());
    CHECK(prepared.derived<DerivedCount>([&] { return DerivedCount{++builds}; }, &ms).value == 1);   // kept
    CHECK_FALSE(ms.has_value());
    CHECK(builds == 1);
    // A build that derives another type (as the environment's tables derive its map).
    CHECK(prepared.derived<DerivedDoubled>([&] { return DerivedDoubled{2 * prepared.derived<DerivedCount>([] { return DerivedCount{-1}; }).value}; }).value == 2);
    CHECK_THROWS_AS(prepared.derived<DerivedFailing>([]() -> DerivedFailing { throw std::runtime_error("no"); }), std::runtime_error);
    CHECK(prepared.derived<DerivedFailing>([] { return DerivedFailing{7}; }).value == 7);
}
