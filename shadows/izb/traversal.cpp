// Irregular z-buffer, stage 7: every occluder tested against the receivers in the texels it
// covers (RTR4 Figure 7.30, lower right: "At each texel touched ... all dots in its list are
// tested against the triangle for visibility by the light").
//
// Tiles run in parallel; a tile's task is the only one that reads or writes the receivers of
// its texels, and a receiver's answer is an OR over triangles, so the result does not depend
// on the schedule. The footprint of a triangle that spans several tiles is found again in
// each, from its corners projected once (ProjectedOccluders), rather than stored. Receivers
// are in list order (ListedReceivers), so the covered texels of one row of a tile hold one
// run of receivers, which the occlusion kernel tests a vector at a time.
//
// A cut-out triangle blocks a receiver where its segment meets the triangle at a solid
// texel: the crossing kernel lists the run's hits with their barycentric coordinates, and
// each is held to the reference's own rule, CasterTransmission::solidAt (the nearest texel
// of the interpolated texture coordinate against the cutoff). Solid triangles never take
// that path, so a scene without cut-outs runs as before.
#include <algorithm>

#include <tbb/parallel_for.h>

#include "shadows/izb/izb.h"
#include "shadows/izb/kernels.h"

namespace shadowlab::izb {
namespace {

struct TileWork {
    uint64_t texelPairs = 0, segmentTests = 0, cutOutHits = 0;
};

struct Traversal {
    const LightGrid& grid;
    const TexelLists& lists;
    const ProjectedOccluders& occluders;
    const Kernels& kernels;
    const CasterTransmission* cutOuts;
    ReceiverColumns receivers;
    OccluderTriangle occluder;   // the light filled in once; the vertices per triangle
    Occlusion& out;
    std::vector<SegmentHit> hits;   // a cut-out's crossings in one run

    // One triangle over the texels [begin, end) of one row of a tile (consecutive numbers):
    // their receivers are one run.
    void testRow(uint32_t t, size_t begin, size_t end, TileWork& work) {
        const uint32_t first = lists.first[begin], last = lists.first[end];
        if (first == last) return;
        for (size_t texel = begin; texel < end; ++texel) {
            if (lists.length(texel) == 0) continue;
            ++out.occluders[texel];
            ++work.texelPairs;
        }
        work.segmentTests += last - first;
        if (cutOuts && occluders.world.triangleCutOut[t] >= 0) {
            testCutOutRun(t, first, last, work);
        } else {
            kernels.occlusion(occluder, receivers, first, last, out.blocked.data());
        }
    }

    void testCutOutRun(uint32_t t, uint32_t first, uint32_t last, TileWork& work) {
        if (hits.size() < last - first) hits.resize(last - first);
        const uint32_t count = kernels.crossings(occluder, receivers, first, last, hits.data());
        work.cutOutHits += count;
        for (uint32_t h = 0; h < count; ++h) {
            uint8_t& blocked = out.blocked[hits[h].receiver];
            if (!blocked && cutOuts->solidAt(t, hits[h].u, hits[h].v)) blocked = 1;
        }
    }

    // One triangle over the texels of tile (view, tx, ty) its footprint touches.
    void testTriangle(int view, int tx, int ty, uint32_t t, TileWork& work) {
        const glm::uvec3& index = occluders.world.triangles[t];
        for (int k = 0; k < 3; ++k) {
            const glm::vec3& p = occluders.world.positions[index[k]];
            for (int c = 0; c < 3; ++c) occluder.vertex[3 * k + c] = p[c];
        }
        const int R = grid.resolution;
        const LightPolygon polygon = occluders.polygon(grid, view, t);
        const TexelRange rows = coveredRows(polygon, R);
        for (int j = std::max(rows.begin, ty * kTileSize); j < std::min(rows.end, (ty + 1) * kTileSize); ++j) {
            const TexelRange columns = coveredColumns(polygon, j, j + 1, R);
            const int begin = std::max(columns.begin, tx * kTileSize), end = std::min(columns.end, (tx + 1) * kTileSize);
            if (begin >= end) continue;
            const size_t first = grid.texelIndex(view, begin, j);
            testRow(t, first, first + size_t(end - begin), work);
        }
    }
};

}  // namespace

Occlusion traverseOccluders(const LightGrid& grid, const HomogeneousLight& light, const ListedReceivers& receivers,
                            const TexelLists& lists, const TileBins& bins, const ProjectedOccluders& occluders,
                            const CasterTransmission* cutOuts, raster::SimdLevel simd) {
    Occlusion out;
    out.blocked.assign(receivers.size(), 0);
    out.occluders.assign(grid.texelCount(), 0);
    const size_t tiles = bins.triangles.first.size() - 1;
    std::vector<TileWork> work(tiles);
    const ReceiverColumns columns{receivers.x.data(), receivers.y.data(), receivers.z.data(), receivers.tFar.data()};
    const OccluderTriangle lightOnly{{}, {light.x, light.y, light.z, light.w}};
    const Kernels kernelTable = kernels(simd);
    const int side = bins.tilesPerSide;
    tbb::parallel_for(size_t(0), tiles, [&](size_t tile) {
        const int view = int(tile / (size_t(side) * side)), ty = int(tile / side % side), tx = int(tile % side);
        Traversal traversal{grid, lists, occluders, kernelTable, cutOuts, columns, lightOnly, out, {}};
        for (uint32_t e = bins.triangles.first[tile]; e < bins.triangles.first[tile + 1]; ++e) {
            traversal.testTriangle(view, tx, ty, bins.triangles.entry[e], work[tile]);
        }
    });
    for (const TileWork& w : work) {
        out.texelPairs += w.texelPairs, out.segmentTests += w.segmentTests, out.cutOutHits += w.cutOutHits;
    }
    return out;
}

}  // namespace shadowlab::izb
