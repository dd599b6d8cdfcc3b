// The setup and tile kernels (setup_triangles.inl, tile_raster.inl) compiled for the
// avx2 SIMD types. This file is compiled with that instruction set's flags
// (raster/CMakeLists.txt); it includes only plain-data headers besides the kernels, so no
// inline function built for a wider ISA can be picked by the linker for the rest of the
// program.
#include "raster/simd/simd_avx2.h"
#include "raster/kernel_table.h"

namespace shadowlab::raster::isa_avx2 {
namespace simd = shadowlab::simd_avx2;
#include "raster/setup_triangles.inl"
#include "raster/tile_raster.inl"
}  // namespace shadowlab::raster::isa_avx2

namespace shadowlab::raster {
const RasterKernels& rasterKernelsAvx2() { return isa_avx2::kernels(); }
}  // namespace shadowlab::raster
