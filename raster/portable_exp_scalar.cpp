// portable::exp over arrays (portable_exp.inl) compiled for the scalar SIMD types: the twin
// of the vector builds, and the one that takes every run's tail.
#include "raster/portable_constants.h"
#include "raster/portable_exp_kernel.h"
#include "raster/simd/simd_scalar.h"

namespace shadowlab::portable {

namespace exp_scalar {
namespace simd = shadowlab::simd_scalar;
#include "raster/portable_exp.inl"
}  // namespace exp_scalar

ExpKernel expKernelScalar() { return {simd_scalar::kWidth64, exp_scalar::expRunLanes}; }

}  // namespace shadowlab::portable
