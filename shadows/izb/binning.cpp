// Irregular z-buffer, stage 5: occluders sorted into tiles of the light grid, so that the
// traversal can give each tile (and the receivers in its texels) to one task.
//
// The same scheme as raster/bin.cpp: chunks of triangles in parallel, each recording the
// (tile, triangle) pairs of its footprints, then a counting sort by tile over the chunks
// in order, so every tile's list is in triangle order for any number of threads.
// Tiles without receivers get no entries: nothing there can be shadowed.
#include <algorithm>

#include <tbb/parallel_for.h>

#include "shadows/izb/izb.h"

namespace shadowlab::izb {
namespace {

constexpr size_t kTrianglesPerTask = 8192;   // triangles per binning task

struct TilePair {
    uint32_t tile, triangle;
};

// A tile's texels are consecutive numbers, so its receivers are one range of the lists.
std::vector<uint8_t> tilesWithReceivers(const LightGrid& grid, const TexelLists& lists, int tilesPerSide) {
    std::vector<uint8_t> used(grid.views.size() * size_t(tilesPerSide) * tilesPerSide, 0);
    constexpr size_t kTexelsPerTile = size_t(kTileSize) * kTileSize;
    for (size_t tile = 0; tile < used.size(); ++tile) {
        used[tile] = lists.first[tile * kTexelsPerTile] != lists.first[(tile + 1) * kTexelsPerTile];
    }
    return used;
}

// The tiles one triangle's footprint touches in one view, band of tile rows by band.
void binTriangle(const LightGrid& grid, int view, uint32_t index, const ProjectedOccluders& occluders, int tilesPerSide,
                 const std::vector<uint8_t>& used, std::vector<TilePair>& pairs) {
    const LightPolygon polygon = occluders.polygon(grid, view, index);
    const TexelRange rows = coveredRows(polygon, grid.resolution);
    if (rows.empty()) return;
    for (int ty = rows.begin / kTileSize; ty <= (rows.end - 1) / kTileSize; ++ty) {
        const TexelRange columns = coveredColumns(polygon, ty * kTileSize, (ty + 1) * kTileSize, grid.resolution);
        if (columns.empty()) continue;
        for (int tx = columns.begin / kTileSize; tx <= (columns.end - 1) / kTileSize; ++tx) {
            const uint32_t tile = uint32_t((view * tilesPerSide + ty) * tilesPerSide + tx);
            if (used[tile]) pairs.push_back({tile, index});
        }
    }
}

}  // namespace

TileBins binOccluders(const LightGrid& grid, const TexelLists& lists, const ProjectedOccluders& occluders) {
    TileBins bins;
    bins.tilesPerSide = tilesPerSide(grid.resolution);
    const std::vector<uint8_t> used = tilesWithReceivers(grid, lists, bins.tilesPerSide);
    const size_t triangles = occluders.world.triangles.size();
    const size_t chunks = (triangles + kTrianglesPerTask - 1) / kTrianglesPerTask;
    std::vector<std::vector<TilePair>> pairs(chunks);
    tbb::parallel_for(size_t(0), chunks, [&](size_t c) {
        for (size_t t = c * kTrianglesPerTask; t < std::min(triangles, (c + 1) * kTrianglesPerTask); ++t) {
            for (int view = 0; view < int(grid.views.size()); ++view) {
                binTriangle(grid, view, uint32_t(t), occluders, bins.tilesPerSide, used, pairs[c]);
            }
        }
    });
    // Concatenated in chunk order, then sorted by tile: each tile's triangles stay in order.
    size_t total = 0;
    for (const std::vector<TilePair>& chunk : pairs) total += chunk.size();
    std::vector<uint32_t> tile, triangle;
    tile.reserve(total), triangle.reserve(total);
    for (const std::vector<TilePair>& chunk : pairs) {
        for (const TilePair& p : chunk) tile.push_back(p.tile), triangle.push_back(p.triangle);
    }
    bins.triangles = countingSort(tile, used.size(), triangle);
    return bins;
}

}  // namespace shadowlab::izb
