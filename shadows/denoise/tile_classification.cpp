#include "shadows/denoise/tile_classification.h"

#include <algorithm>
#include <stdexcept>

namespace shadowlab {
namespace {

TileClass classify(std::span<const float> v, std::span<const float> accumulated, const GBuffer& g, int x0, int y0,
                   int size) {
    bool anyLit = false, anyShadowed = false, anyOther = false;
    for (int y = y0; y < std::min(y0 + size, g.height); ++y) {
        for (int x = x0; x < std::min(x0 + size, g.width); ++x) {
            const size_t k = g.index(x, y);
            if (!g.hit[k]) continue;
            // Fully lit or fully shadowed in this frame and in the history it was blended with.
            if (v[k] == 1.0f && accumulated[k] == 1.0f) anyLit = true;
            else if (v[k] == 0.0f && accumulated[k] == 0.0f) anyShadowed = true;
            else anyOther = true;
        }
    }
    if (anyOther || (anyLit && anyShadowed)) return TileClass::Filtered;
    return anyLit ? TileClass::Lit : anyShadowed ? TileClass::Shadowed : TileClass::Empty;
}

}  // namespace

TileClasses classifyTiles(std::span<const float> v, std::span<const float> accumulated, const GBuffer& g,
                          int tileSize) {
    if (tileSize < 1 || tileSize > 64) throw std::invalid_argument("tile classification: tile size outside 1..64");
    TileClasses c;
    c.size = tileSize;
    c.columns = (g.width + tileSize - 1) / tileSize;
    c.rows = (g.height + tileSize - 1) / tileSize;
    c.tiles.resize(size_t(c.columns) * size_t(c.rows));
    for (int ty = 0; ty < c.rows; ++ty) {
        for (int tx = 0; tx < c.columns; ++tx) {
            const TileClass t = classify(v, accumulated, g, tx * tileSize, ty * tileSize, tileSize);
            c.tiles[size_t(ty) * size_t(c.columns) + size_t(tx)] = t;
            c.surfaced += t != TileClass::Empty;
            c.skipped += t == TileClass::Lit || t == TileClass::Shadowed;
        }
    }
    return c;
}

std::vector<uint8_t> TileClasses::filteredPixels(const GBuffer& g) const {
    std::vector<uint8_t> mask(g.pixelCount(), 0);
    for (int y = 0; y < g.height; ++y)
        for (int x = 0; x < g.width; ++x)
            mask[g.index(x, y)] = tiles[size_t(y / size) * size_t(columns) + size_t(x / size)] == TileClass::Filtered;
    return mask;
}

std::vector<float> TileClasses::classImage(const GBuffer& g) const {
    std::vector<float> image(g.pixelCount(), 0.0f);
    for (int y = 0; y < g.height; ++y)
        for (int x = 0; x < g.width; ++x)
            image[g.index(x, y)] = float(tiles[size_t(y / size) * size_t(columns) + size_t(x / size)]);
    return image;
}

}  // namespace shadowlab
