// portable::exp (portable_math.h) over an array, a vector of doubles at a time: the same
// sequence of IEEE operations in every lane, so every SIMD level gives portable::exp's bits
// for every value (tests/raster/test_portable_math.cpp). Written once (portable_exp.inl)
// and compiled for scalar, AVX2 and AVX-512 (cmake/isa_kernels.cmake), for the passes that take
// an exponential per texel or per pixel (the exponential shadow maps' warps).
#pragma once

#include <cstddef>

#include "raster/portable_exp_kernel.h"
#include "raster/tile_kernels.h"

namespace shadowlab::portable {

// out[k] = exp(x[k]) for k < count; out may be x.
void expRun(raster::SimdLevel simd, const double* x, double* out, size_t count);

}  // namespace shadowlab::portable
