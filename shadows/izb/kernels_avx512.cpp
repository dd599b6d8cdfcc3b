// The irregular z-buffer's kernels (segments.inl, occlusion.inl) compiled for the avx512 SIMD
// types, with that instruction set's flags (shadows/CMakeLists.txt). It includes only
// plain-data headers besides the kernels, so no inline function built for a wider
// instruction set can be picked by the linker for the rest of the program.
#include "raster/simd/simd_avx512.h"
#include "shadows/izb/kernels.h"

namespace shadowlab::izb {
namespace kernels_avx512 {
namespace simd = shadowlab::simd_avx512;
#include "shadows/izb/segments.inl"
#include "shadows/izb/occlusion.inl"
}  // namespace kernels_avx512

Kernels kernelsAvx512() { return {kernels_avx512::computeSegments, kernels_avx512::blockRun}; }

}  // namespace shadowlab::izb
