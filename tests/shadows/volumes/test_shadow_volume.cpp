// shadow-volume (shadows/volumes/shadow_volume.cpp): silhouettes on a cube from known light
// positions, the exact techniques' bound on the built-in scenes (test::kExactBoundPercent:
// at most 0.01% of pixels misclassified against the exact reference, each within one pixel
// of a reference shadow boundary), z-pass against z-fail, and the same bytes for 1 and 2 threads and every
// SIMD level.
#include <doctest/doctest.h>

#include <algorithm>

#include "raster/thread_count.h"
#include "scenes/edge_adjacency.h"
#include "scenes/procedural.h"
#include "shadows/silhouettes/silhouette.h"
#include "shadows/volumes/counting_mode.h"
#include "tests/shadows/shadow_test_support.h"

using namespace shadowlab;

namespace {

// Silhouette edges of a mesh standing in world space as it is (one instance at the origin).
std::vector<SilhouetteEdge> silhouetteOf(const Mesh& mesh, const glm::vec3& lightPosition) {
    const EdgeAdjacency adjacency = buildEdgeAdjacency(mesh.positions, mesh.triangles);
    const glm::dvec4 light(glm::dvec3(lightPosition), 1.0);
    std::vector<int8_t> sign;
    for (const glm::uvec3& t : mesh.triangles) {
        const bool lit = facesLight(light, mesh.positions[t.x], mesh.positions[t.y], mesh.positions[t.z]);
        sign.push_back(int8_t(casterSigns(lit, adjacency.closed).light));
    }
    return silhouetteEdges(adjacency, sign, 0);
}

// The same cube with every triangle given its own three vertices: only welding finds edges.
Mesh unwelded(const Mesh& mesh) {
    Mesh soup;
    for (const glm::uvec3& t : mesh.triangles) {
        const uint32_t base = uint32_t(soup.positions.size());
        for (int k = 0; k < 3; ++k) soup.positions.push_back(mesh.positions[t[k]]);
        soup.triangles.emplace_back(base, base + 1, base + 2);
    }
    return soup;
}

}  // namespace

TEST_CASE("shadow-volume: edge adjacency welds duplicated vertices and finds a cube closed") {
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
    CHECK(prepared.preparationTimes().size() == 1);   // flattened only: nothing built yet
    const std::vector<EdgeAdjacency>* first = &prepared.edgeAdjacency();
    CHECK(&prepared.edgeAdjacency() == first);         // the same data, not rebuilt
    CHECK((*first)[0].closed);
    const auto times = prepared.preparationTimes();
    REQUIRE(times.size() == 2);
    CHECK(times[1].first == "edge_adjacency_ms");
    CHECK(times[1].second >= 0.0);
    // An edited copy is another prepared scene with its own edges: without one triangle
    // the box is open.
    scene.meshes[0].triangles.pop_back();
    const PreparedScene edited(scene);
    CHECK_FALSE(edited.edgeAdjacency()[0].closed);
    CHECK(edited.edgeAdjacency()[0].edges.size() ==
          buildEdgeAdjacency(scene.meshes[0].positions, scene.meshes[0].triangles).edges.size());
    CHECK(prepared.edgeAdjacency()[0].closed);
}

TEST_CASE("shadow-volume: silhouette of a unit cube from known light positions") {
    const Mesh cube = makeBox(glm::vec3(0.0f), glm::vec3(1.0f));
    SUBCASE("light straight above the centre: the four top edges") {
        for (const Mesh& mesh : {cube, unwelded(cube)}) {
            const std::vector<SilhouetteEdge> edges = silhouetteOf(mesh, {0.5f, 5.0f, 0.5f});
            REQUIRE(edges.size() == 4);
            for (const SilhouetteEdge& e : edges) {
                CHECK(mesh.positions[e.from].y == 1.0f);
                CHECK(mesh.positions[e.to].y == 1.0f);
            }
        }
    }
    SUBCASE("light off a corner: the hexagon between the three lit and three dark faces") {
        const std::vector<SilhouetteEdge> edges = silhouetteOf(unwelded(cube), {3.0f, 4.0f, 2.0f});
        CHECK(edges.size() == 6);
        // A closed loop: every vertex is left exactly as often as it is entered.
        for (const SilhouetteEdge& e : edges) {
            const auto entered = std::count_if(edges.begin(), edges.end(), [&](const SilhouetteEdge& o) { return o.to == e.from; });
            CHECK(entered == 1);
        }
    }
    SUBCASE("an open quad casts from its boundary whichever side faces the light") {
        const Mesh quad = makeGrid(glm::vec2(2.0f), glm::ivec2(4));
        const std::vector<SilhouetteEdge> above = silhouetteOf(quad, {0.0f, 3.0f, 0.0f});
        const std::vector<SilhouetteEdge> below = silhouetteOf(quad, {0.0f, -3.0f, 0.0f});
        CHECK(above.size() == 16);   // the 4 x 4 grid's boundary edges
        REQUIRE(below.size() == 16);
        CHECK(below[0].from == above[0].to);   // walked the other way: reversed caster
    }
}

TEST_CASE("shadow-volume: built-in scenes within 0.01% of the reference, errors only next to shadow boundaries") {
    for (const char* name : {"sphere-box", "bunny"}) {
        const test::HardScene s(name);
        test::requireBound(s, s.run("shadow-volume"), name);
    }
}

TEST_CASE("shadow-volume: throughput (4.1 M triangles) within 0.01% of the reference") {
    const test::HardScene s("throughput");
    test::requireBound(s, s.run("shadow-volume"), "throughput");
}

TEST_CASE("shadow-volume: z-pass and z-fail give the same stencil when the camera is outside every volume") {
    for (const char* name : {"sphere-box", "bunny"}) {
        const test::HardScene s(name);
        const Camera& c = s.scene.camera;
        CHECK_FALSE(nearPlaneMayBeShadowed(c, homogeneousLight(s.scene.lights[0]), instanceBounds(s.scene, s.world)));
        const ShadowOutputs pass = s.run("shadow-volume", {{"mode", "zpass"}});
        const ShadowOutputs fail = s.run("shadow-volume", {{"mode", "zfail"}});
        CHECK(test::stat(s.run("shadow-volume"), "zfail_flag") == 0.0);
        CHECK(pass.visibility == fail.visibility);
        size_t differentCounts = 0;
        for (size_t k = 0; k < pass.stencil.size(); ++k) differentCounts += s.gbuffer.hit[k] && pass.stencil[k] != fail.stencil[k];
        CHECK(differentCounts == 0);
        // z-fail draws the caps too: more fill for the same answer.
        CHECK(test::stat(fail, "fill_fragments") > test::stat(pass, "fill_fragments"));
    }
}

TEST_CASE("shadow-volume: the same bytes for 1 and 2 threads and every SIMD level") {
    const test::HardScene s("sphere-box");
    const auto runWith = [&](int threads, raster::SimdLevel simd) {
        return withThreads(threads, [&] { return s.run("shadow-volume", {{"mode", "zfail"}}, simd); });
    };
    const ShadowOutputs one = runWith(1, raster::bestSimdLevel());
    for (const raster::SimdLevel simd : {raster::SimdLevel::Scalar, raster::bestSimdLevel()}) {
        const ShadowOutputs two = runWith(2, simd);
        CHECK(one.visibility == two.visibility);
        CHECK(one.stencil == two.stencil);
        CHECK(test::stat(one, "fill_fragments") == test::stat(two, "fill_fragments"));
    }
}
