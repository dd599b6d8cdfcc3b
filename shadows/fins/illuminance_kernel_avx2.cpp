// The illuminance buffer's kernels (illuminance_kernel.inl) compiled for the avx2 SIMD types, with
// that instruction set's flags (shadows/CMakeLists.txt). It includes only plain-data headers
// besides the kernels, so no inline function built for a wider instruction set can be
// picked by the linker for the rest of the program.
#include "raster/simd/simd_avx2.h"
#include "shadows/fins/illuminance_kernel.h"

namespace shadowlab::fins {
namespace illuminance_avx2 {
namespace simd = shadowlab::simd_avx2;
#include "shadows/fins/illuminance_kernel.inl"
}  // namespace illuminance_avx2

IlluminanceKernels illuminanceKernelsAvx2() {
    return {simd_avx2::kWidth64, illuminance_avx2::placeReceivers, illuminance_avx2::illuminate};
}

}  // namespace shadowlab::fins
