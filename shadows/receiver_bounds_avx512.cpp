// The receivers' bounds (receiver_bounds.inl) compiled for the avx512 SIMD types, with that
// instruction set's flags (shadows/CMakeLists.txt). It includes only plain-data headers
// besides the kernel, so no inline function built for a wider instruction set can be
// picked by the linker for the rest of the program.
#include "raster/simd/simd_avx512.h"
#include "shadows/receiver_bounds.h"

namespace shadowlab {
namespace receiver_bounds_avx512 {
namespace simd = shadowlab::simd_avx512;
#include "shadows/receiver_bounds.inl"
}  // namespace receiver_bounds_avx512

const BoundsKernels& boundsKernelsAvx512() { return receiver_bounds_avx512::kernels(); }

}  // namespace shadowlab
