// The irregular z-buffer's kernels (segments.inl, occlusion.inl) compiled for the avx2 SIMD
// types, with that instruction set's flags (shadows/CMakeLists.txt). It includes only
// plain-data headers besides the kernels, so no inline function built for a wider
// instruction set can be picked by the linker for the rest of the program.
#include "raster/simd/simd_avx2.h"
#include "shadows/izb/kernels.h"

namespace shadowlab::izb {
namespace kernels_avx2 {
namespace simd = shadowlab::simd_avx2;
#include "shadows/izb/segments.inl"
#include "shadows/izb/occlusion.inl"
}  // namespace kernels_avx2

Kernels kernelsAvx2() { return {kernels_avx2::computeSegments, kernels_avx2::blockRun}; }

}  // namespace shadowlab::izb
