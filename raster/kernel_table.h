// The table of tile kernels one instruction set provides (one per fragment output and
// stencil use). Plain declarations only: the per-ISA translation units include it.
#pragma once

#include "raster/triangle_setup.h"

namespace shadowlab::raster {

// Rasterizes one triangle into one tile. tileIndex is row-major over tiles. Adds the
// number of covered pixels (fragments, before any test) to `fragments`.
using TileKernel = void (*)(const TriangleSetup&, int tileIndex, const DrawConstants&, const FramebufferView&,
                            uint64_t& fragments);

inline constexpr int kFragmentOutputCount = 4;

// One kernel per fragment output and stencil use, compiled for one instruction set.
struct TileKernels {
    TileKernel kernel[kFragmentOutputCount][2];
};

const TileKernels& tileKernelsScalar();
const TileKernels& tileKernelsAvx2();
const TileKernels& tileKernelsAvx512();

}  // namespace shadowlab::raster
