#include "raster/bin.h"

#include <tbb/parallel_for.h>

#include "raster/fixed_point.h"

namespace shadowlab::raster {
namespace {

struct TileRange {
    int x0, y0, x1, y1;   // inclusive
};

TileRange tilesTouched(const TriangleSetup& t) {
    return {t.minX >> kTileShift, t.minY >> kTileShift, (t.maxX - 1) >> kTileShift, (t.maxY - 1) >> kTileShift};
}

}  // namespace

void countTiles(SetupChunk& chunk, int tilesX, int tilesY) {
    chunk.tileCounts.assign(size_t(tilesX) * size_t(tilesY), 0);
    chunk.entryCount = 0;
    for (const TriangleSetup& t : chunk.triangles) {
        const TileRange r = tilesTouched(t);
        chunk.entryCount += size_t(r.x1 - r.x0 + 1) * size_t(r.y1 - r.y0 + 1);
        for (int ty = r.y0; ty <= r.y1; ++ty) {
            for (int tx = r.x0; tx <= r.x1; ++tx) ++chunk.tileCounts[size_t(ty) * size_t(tilesX) + size_t(tx)];
        }
    }
}

void fillBins(std::vector<SetupChunk>& chunks, size_t first, size_t last, int tilesX, int tilesY, TileBins& bins) {
    const size_t tileCount = size_t(tilesX) * size_t(tilesY);
    // Prefix sum in (tile, chunk) order: chunk c's range in tile t follows chunks first..c-1.
    std::vector<size_t> cursor((last - first) * tileCount);
    bins.start.assign(tileCount + 1, 0);
    size_t total = 0;
    for (size_t t = 0; t < tileCount; ++t) {
        bins.start[t] = total;
        for (size_t c = first; c < last; ++c) {
            cursor[(c - first) * tileCount + t] = total;
            total += chunks[c].tileCounts[t];
        }
    }
    bins.start[tileCount] = total;
    bins.entries.resize(total);

    tbb::parallel_for(first, last, [&](size_t c) {
        SetupChunk& chunk = chunks[c];
        size_t* next = cursor.data() + (c - first) * tileCount;
        // Setup left every `varyings` null: a draw without planes writes no triangle here,
        // which would otherwise dirty every cache line of the chunk a second time.
        const bool planes = !chunk.planes.empty();
        for (size_t i = 0; i < chunk.triangles.size(); ++i) {
            TriangleSetup& t = chunk.triangles[i];
            if (planes) t.varyings = chunk.planes.data() + chunk.planeStart[i];
            const TileRange r = tilesTouched(t);
            for (int ty = r.y0; ty <= r.y1; ++ty) {
                for (int tx = r.x0; tx <= r.x1; ++tx) bins.entries[next[size_t(ty) * size_t(tilesX) + size_t(tx)]++] = &t;
            }
        }
    });
}

}  // namespace shadowlab::raster
