// The tile kernels compiled for each instruction set, and the choice between them.
#pragma once

#include <string>

#include "raster/kernel_table.h"

namespace shadowlab::raster {

enum class SimdLevel { Scalar, Avx2, Avx512 };

// The widest level this CPU runs, and the kernels of a level (which must be supported).
SimdLevel bestSimdLevel();
bool simdLevelSupported(SimdLevel level);
const TileKernels& tileKernels(SimdLevel level);

const char* simdLevelName(SimdLevel level);
// Parses "scalar", "avx2", "avx512" or "auto" (the best supported); throws std::invalid_argument.
SimdLevel parseSimdLevel(const std::string& name);

}  // namespace shadowlab::raster
