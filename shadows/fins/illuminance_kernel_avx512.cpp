// The illuminance buffer's kernels (illuminance_kernel.inl) compiled for the avx512 SIMD types, with
// that instruction set's flags (shadows/CMakeLists.txt). It includes only plain-data headers
// besides the kernels, so no inline function built for a wider instruction set can be
// picked by the linker for the rest of the program.
#include "raster/simd/simd_avx512.h"
#include "shadows/fins/illuminance_kernel.h"

namespace shadowlab::fins {
namespace illuminance_avx512 {
namespace simd = shadowlab::simd_avx512;
#include "shadows/fins/illuminance_kernel.inl"
}  // namespace illuminance_avx512

IlluminanceKernels illuminanceKernelsAvx512() {
    return {simd_avx512::kWidth64, illuminance_avx512::placeReceivers, illuminance_avx512::illuminate};
}

}  // namespace shadowlab::fins
