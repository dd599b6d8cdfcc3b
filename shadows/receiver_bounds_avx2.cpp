// The receivers' bounds (receiver_bounds.inl) compiled for the avx2 SIMD types, with that
// instruction set's flags (shadows/CMakeLists.txt). It includes only plain-data headers
// besides the kernel, so no inline function built for a wider instruction set can be
// picked by the linker for the rest of the program.
#include "raster/simd/simd_avx2.h"
#include "shadows/receiver_bounds.h"

namespace shadowlab {
namespace receiver_bounds_avx2 {
namespace simd = shadowlab::simd_avx2;
#include "shadows/receiver_bounds.inl"
}  // namespace receiver_bounds_avx2

const BoundsKernels& boundsKernelsAvx2() { return receiver_bounds_avx2::kernels(); }

}  // namespace shadowlab
