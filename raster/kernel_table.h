// The rasterizer's kernels one instruction set provides: triangle setup, and a tile kernel
// per fragment output and stencil use. Plain declarations only: the per-ISA translation
// units include it.
#pragma once

#include "raster/setup_kernel.h"
#include "raster/triangle_setup.h"

namespace shadowlab::raster {

// A tile as the kernels address it: its index, row-major over tiles, and its first pixel.
struct Tile {
    int index, x, y;
};

inline Tile tileAt(int index, int tilesX) {
    return {index, (index % tilesX) * kTileSize, (index / tilesX) * kTileSize};
}

// Rasterizes one triangle into one tile. Adds the number of covered pixels (fragments,
// before any test) to `fragments`.
using TileKernel = void (*)(const TriangleSetup&, const Tile& tile, const DrawConstants&, const FramebufferView&,
                            uint64_t& fragments);

inline constexpr int kFragmentOutputCount = 5;

// Compiled for one instruction set: setup, and one tile kernel per fragment output, stencil
// use and alpha test.
struct RasterKernels {
    SetupKernel setup;
    TileKernel kernel[kFragmentOutputCount][2][2];
};

const RasterKernels& rasterKernelsScalar();
const RasterKernels& rasterKernelsAvx2();
const RasterKernels& rasterKernelsAvx512();

}  // namespace shadowlab::raster
