// portable::exp over arrays (portable_exp.inl) compiled for the avx2 SIMD types, with that
// instruction set's flags (raster/CMakeLists.txt); it includes only plain-data headers
// besides the kernel, so no inline function built for a wider instruction set can be
// picked by the linker for the rest of the program.
#include "raster/portable_constants.h"
#include "raster/portable_exp_kernel.h"
#include "raster/simd/simd_avx2.h"

namespace shadowlab::portable {

namespace exp_avx2 {
namespace simd = shadowlab::simd_avx2;
#include "raster/portable_exp.inl"
}  // namespace exp_avx2

ExpKernel expKernelAvx2() { return {simd_avx2::kWidth64, exp_avx2::expRunLanes}; }

}  // namespace shadowlab::portable
