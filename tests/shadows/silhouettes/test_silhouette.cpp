// Silhouette edges with respect to a light (shadows/silhouettes/silhouette.h) on meshes with
// known answers: a cube from known light positions, welded or not, and an open quad.
#include <doctest/doctest.h>

#include <algorithm>

#include "scenes/edge_adjacency.h"
#include "scenes/procedural.h"
#include "shadows/silhouettes/silhouette.h"
#include "tests/scenes/unwelded_mesh.h"

using namespace shadowlab;
using test::unwelded;

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

}  // namespace

TEST_CASE("silhouette of a unit cube from known light positions") {
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
