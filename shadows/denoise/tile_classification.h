// Tile classification, after AMD FidelityFX Shadow Denoiser's public description (GPUOpen,
// "FidelityFX Denoiser 1.3": "a tile classification pass to skip work on areas without
// spatial variance in the shadow mask"): the image cut into square tiles, and a tile
// whose every surface pixel is fully lit, or every one fully in shadow, this frame and in
// its history, needs no spatial filter: nothing there is noise. The others are filtered.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "shading/gbuffer.h"

namespace shadowlab {

enum class TileClass : uint8_t {
    Empty = 0,      // no surface pixel
    Lit = 1,        // V = 1 now and in history at every surface pixel
    Shadowed = 2,   // V = 0 now and in history at every surface pixel
    Filtered = 3,   // the rest
};

struct TileClasses {
    int size = 8, columns = 0, rows = 0;
    std::vector<TileClass> tiles;   // row-major
    size_t skipped = 0, surfaced = 0;   // Lit + Shadowed tiles; tiles not Empty

    // Per pixel of the G-buffer: 1 in a Filtered tile.
    std::vector<uint8_t> filteredPixels(const GBuffer& gbuffer) const;
    // Per pixel: its tile's class as a number (the enum's), for the debug buffer.
    std::vector<float> classImage(const GBuffer& gbuffer) const;
};

// `visibility` is this frame's V, `accumulated` the history blended with it (a pixel
// without history: its V), both per G-buffer pixel. Throws std::invalid_argument for a
// tile size outside 1..64.
TileClasses classifyTiles(std::span<const float> visibility, std::span<const float> accumulated,
                          const GBuffer& gbuffer, int tileSize);

}  // namespace shadowlab
