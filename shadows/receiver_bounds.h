// The bounds of the receivers a light's view must cover (light_view.cpp), as a vector
// kernel: over a run of G-buffer points, the componentwise minima and maxima of where they
// lie, in double precision. Written once (receiver_bounds.inl) against the SIMD types of
// raster/simd/ and compiled for scalar, AVX2 and AVX-512 (cmake/isa_kernels.cmake); each lane
// does the operations of the plain double expression (glm's matrix product, in its order),
// and minima and maxima are exact in any order, so every level gives the same bounds.
//
// Plain data only: the per-ISA translation units include this header, and no inline
// function built for a wider instruction set may reach the rest of the program.
#pragma once

#include <cstddef>
#include <cstdint>

namespace shadowlab {

// What is bounded for each point P:
//   kWorldBox         P itself;
//   kOrthographicView q = viewFromWorld (P, 1): (q.x, q.y, -q.z);
//   kPerspectiveView  (q.x / d, q.y / d, d) with d = -q.z, the tangents of the direction and
//                     the depth; a point with d <= 0 (beside or behind the apex) is flagged.
enum BoundsSpace : int { kWorldBox, kOrthographicView, kPerspectiveView, kBoundsSpaceCount };

struct BoundsRun {
    const float* position;      // x, y, z per point
    const uint8_t* served;      // nonzero where the point counts
    size_t count;               // points in the run; the kernels take a multiple of their width
    const double* matrix;       // viewFromWorld, 16 values column-major (as glm); unused for kWorldBox
};

struct BoundsResult {
    double lo[3], hi[3];        // +inf and -inf where no point counted
    bool behindApex;            // kPerspectiveView: some counted point had d <= 0 (or NaN)
};

// Merges `run` into `result` (which starts as emptyBounds()).
using BoundsKernel = void (*)(const BoundsRun& run, BoundsResult& result);

struct BoundsKernels {
    int width;                  // the points a vector step takes
    BoundsKernel space[kBoundsSpaceCount];
};
const BoundsKernels& boundsKernelsScalar();
const BoundsKernels& boundsKernelsAvx2();
const BoundsKernels& boundsKernelsAvx512();

inline BoundsResult emptyBounds() {
    return {{__builtin_inf(), __builtin_inf(), __builtin_inf()}, {-__builtin_inf(), -__builtin_inf(), -__builtin_inf()}, false};
}

}  // namespace shadowlab
