// The receivers' bounds (receiver_bounds.inl) compiled for the scalar SIMD types: the plain
// twin of the vector builds, and the one that takes every run's tail.
#include "raster/simd/simd_scalar.h"
#include "shadows/receiver_bounds.h"

namespace shadowlab {
namespace receiver_bounds_scalar {
namespace simd = shadowlab::simd_scalar;
#include "shadows/receiver_bounds.inl"
}  // namespace receiver_bounds_scalar

const BoundsKernels& boundsKernelsScalar() { return receiver_bounds_scalar::kernels(); }

}  // namespace shadowlab
