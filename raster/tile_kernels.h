// The rasterizer's kernels (setup and tiles) compiled for each instruction set, and the
// choice between them.
#pragma once

#include <string>

#include "raster/kernel_table.h"

namespace shadowlab::raster {

enum class SimdLevel { Scalar, Avx2, Avx512 };

// The widest level this CPU runs, and the kernels of a level (which must be supported).
SimdLevel bestSimdLevel();
bool simdLevelSupported(SimdLevel level);
const RasterKernels& rasterKernels(SimdLevel level);

// Throws std::invalid_argument naming the level unless this CPU supports it.
void requireSimdLevel(SimdLevel level);

// What the function of the level returns: scalar(), avx2() or avx512(), for the families of
// kernels compiled once per instruction set (the tile kernels, the shadow lookup's, ...).
// Throws as requireSimdLevel.
template <class Scalar, class Avx2, class Avx512>
decltype(auto) forSimdLevel(SimdLevel level, Scalar scalar, Avx2 avx2, Avx512 avx512) {
    requireSimdLevel(level);
    switch (level) {
        case SimdLevel::Avx2: return avx2();
        case SimdLevel::Avx512: return avx512();
        case SimdLevel::Scalar: break;
    }
    return scalar();
}

const char* simdLevelName(SimdLevel level);
// Parses "scalar", "avx2", "avx512" or "auto" (the best supported); throws std::invalid_argument.
SimdLevel parseSimdLevel(const std::string& name);

}  // namespace shadowlab::raster
