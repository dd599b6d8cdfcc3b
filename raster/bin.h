// Binning: which triangles each 64x64 tile must rasterize, in submission order.
//
// The front end runs in parallel over chunks of triangles. Each chunk counts, per tile,
// the triangles whose pixel bounds touch the tile; a prefix sum over (tile, chunk) in that
// order gives every chunk a private range in each tile's list; a second parallel pass
// fills the ranges. Chunks are consecutive runs of triangles, so each tile's list is in
// submission order whatever the number of threads (style.md: "threads own tiles").
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "raster/triangle_setup.h"

namespace shadowlab::raster {

// The triangles one chunk of the front end produced.
struct SetupChunk {
    std::vector<TriangleSetup> triangles;
    std::vector<Plane> planes;            // varying planes, referenced by index until binning
    std::vector<uint32_t> planeStart;     // per triangle, its first plane (empty when no planes)
    std::vector<uint32_t> tileCounts;     // per tile, triangles touching it
    size_t entryCount = 0;                // sum of tileCounts
};

struct TileBins {
    std::vector<size_t> start;                   // per tile, first entry; size tiles + 1
    std::vector<const TriangleSetup*> entries;   // all tiles' lists, one after another
};

// Counts the tiles each triangle of the chunk touches (fills tileCounts and entryCount).
void countTiles(SetupChunk& chunk, int tilesX, int tilesY);
// Builds the bins from chunks [first, last), whose tiles were counted; also points every
// triangle at its varying planes, which no longer move.
void fillBins(std::vector<SetupChunk>& chunks, size_t first, size_t last, int tilesX, int tilesY, TileBins& bins);

}  // namespace shadowlab::raster
