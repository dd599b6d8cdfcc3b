// The shadow-map lookup's vector core (lookup_kernel.inl) compiled for the scalar SIMD types,
// with that instruction set's flags (shadows/CMakeLists.txt). It includes only plain-data
// headers besides the kernel, so no inline function built for a wider instruction set can
// be picked by the linker for the rest of the program.
#include "raster/fixed_point.h"
#include "raster/simd/simd_scalar.h"
#include "shadows/maps/lookup_kernel.h"
#include "shadows/maps/receiver_plane_tolerance.h"

namespace shadowlab::lookup_scalar {
namespace simd = shadowlab::simd_scalar;
#include "shadows/maps/lookup_kernel.inl"
}  // namespace shadowlab::lookup_scalar

namespace shadowlab {
const LookupKernels& lookupKernelsScalar() { return lookup_scalar::kernels(); }
}  // namespace shadowlab
