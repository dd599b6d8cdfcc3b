// The shadow-map lookup's vector core (lookup_kernel.inl) compiled for the avx2 SIMD types,
// with that instruction set's flags (shadows/CMakeLists.txt). It includes only plain-data
// headers besides the kernel, so no inline function built for a wider instruction set can
// be picked by the linker for the rest of the program.
#include "raster/fixed_point.h"
#include "raster/simd/simd_avx2.h"
#include "shadows/maps/lookup_kernel.h"
#include "shadows/maps/receiver_plane_tolerance.h"

namespace shadowlab::lookup_avx2 {
namespace simd = shadowlab::simd_avx2;
#include "shadows/maps/lookup_kernel.inl"
}  // namespace shadowlab::lookup_avx2

namespace shadowlab {
const LookupKernels& lookupKernelsAvx2() { return lookup_avx2::kernels(); }
}  // namespace shadowlab
