// The illuminance buffer's kernels (illuminance_kernel.inl) compiled for the scalar SIMD types: the
// plain twin of the vector builds, and the one that takes every run's tail.
#include "raster/simd/simd_scalar.h"
#include "shadows/fins/illuminance_kernel.h"

namespace shadowlab::fins {
namespace illuminance_scalar {
namespace simd = shadowlab::simd_scalar;
#include "shadows/fins/illuminance_kernel.inl"
}  // namespace illuminance_scalar

IlluminanceKernels illuminanceKernelsScalar() {
    return {simd_scalar::kWidth64, illuminance_scalar::placeReceivers, illuminance_scalar::illuminate};
}

}  // namespace shadowlab::fins
