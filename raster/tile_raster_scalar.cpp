// The setup and tile kernels (setup_triangles.inl, tile_raster.inl) compiled for the
// scalar SIMD types. This file is compiled with that instruction set's flags
// (raster/CMakeLists.txt); it includes only plain-data headers besides the kernels, so no
// inline function built for a wider ISA can be picked by the linker for the rest of the
// program.
#include "raster/simd/simd_scalar.h"
#include "raster/kernel_table.h"

namespace shadowlab::raster::isa_scalar {
namespace simd = shadowlab::simd_scalar;
#include "raster/setup_triangles.inl"
#include "raster/tile_raster.inl"
}  // namespace shadowlab::raster::isa_scalar

namespace shadowlab::raster {
const RasterKernels& rasterKernelsScalar() { return isa_scalar::kernels(); }
}  // namespace shadowlab::raster
