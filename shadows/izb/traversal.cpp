// Irregular z-buffer, stage 7: every occluder tested against the receivers in the texels it
// covers (RTR4 Figure 7.30, lower right: "At each texel touched ... all dots in its list are
// tested against the triangle for visibility by the light").
//
// Tiles run in parallel; a tile's task is the only one that reads or writes the receivers of
// its texels, and a receiver's answer is an OR over triangles, so the result does not depend
// on the schedule. The footprint of a triangle that spans several tiles is recomputed in
// each (a few hundred flops) rather than stored.
#include <algorithm>

#include <tbb/parallel_for.h>

#include "shadows/izb/izb.h"

namespace shadowlab::izb {
namespace {

struct TileWork {
    uint64_t texelPairs = 0, segmentTests = 0;
};

struct Traversal {
    const LightGrid& grid;
    const HomogeneousLight& light;
    const Receivers& receivers;
    const TexelLists& lists;
    const WorldGeometry& world;
    Occlusion& out;

    // One triangle against the receivers of one texel; returns the tests made.
    uint64_t testTexel(size_t texel, const glm::dvec3 (&triangle)[3]) {
        uint64_t tests = 0;
        for (uint32_t e = lists.first[texel]; e < lists.first[texel + 1]; ++e) {
            const uint32_t r = lists.entry[e];
            if (out.blocked[r]) continue;   // already shadowed: another OR term cannot change it
            const glm::dvec3 o(receivers.origin[r]);
            out.blocked[r] = segmentBlocked(o, glm::dvec3(light) - light.w * o, receivers.tFar[r], triangle);
            ++tests;
        }
        return tests;
    }

    // One triangle over the texels of tile (view, tx, ty) its footprint touches.
    void testTriangle(int view, int tx, int ty, uint32_t t, TileWork& work) {
        const glm::uvec3& index = world.triangles[t];
        const glm::dvec3 triangle[3] = {glm::dvec3(world.positions[index.x]), glm::dvec3(world.positions[index.y]),
                                        glm::dvec3(world.positions[index.z])};
        const int R = grid.resolution;
        const LightPolygon polygon = projectOccluder(grid, view, triangle);
        const TexelRange rows = coveredRows(polygon, R);
        for (int j = std::max(rows.begin, ty * kTileSize); j < std::min(rows.end, (ty + 1) * kTileSize); ++j) {
            const TexelRange columns = coveredColumns(polygon, j, j + 1, R);
            for (int i = std::max(columns.begin, tx * kTileSize); i < std::min(columns.end, (tx + 1) * kTileSize); ++i) {
                const size_t texel = (size_t(view) * R + j) * R + i;
                if (lists.length(texel) == 0) continue;
                ++out.occluders[texel];
                ++work.texelPairs;
                work.segmentTests += testTexel(texel, triangle);
            }
        }
    }
};

}  // namespace

Occlusion traverseOccluders(const LightGrid& grid, const HomogeneousLight& light, const Receivers& receivers,
                            const TexelLists& lists, const TileBins& bins, const WorldGeometry& world) {
    Occlusion out;
    out.blocked.assign(receivers.size(), 0);
    out.occluders.assign(grid.texelCount(), 0);
    const size_t tiles = bins.triangles.first.size() - 1;
    std::vector<TileWork> work(tiles);
    Traversal traversal{grid, light, receivers, lists, world, out};
    const int side = bins.tilesPerSide;
    tbb::parallel_for(size_t(0), tiles, [&](size_t tile) {
        const int view = int(tile / (size_t(side) * side)), ty = int(tile / side % side), tx = int(tile % side);
        for (uint32_t e = bins.triangles.first[tile]; e < bins.triangles.first[tile + 1]; ++e) {
            traversal.testTriangle(view, tx, ty, bins.triangles.entry[e], work[tile]);
        }
    });
    for (const TileWork& w : work) out.texelPairs += w.texelPairs, out.segmentTests += w.segmentTests;
    return out;
}

}  // namespace shadowlab::izb
