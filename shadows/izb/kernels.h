// The irregular z-buffer's two per-receiver loops as vector kernels: the segments of stage 1
// (segments.inl) and the exact test of stage 6 (occlusion.inl), each written once against
// the SIMD types of raster/simd/ and compiled for scalar, AVX2 and AVX-512 through
// kernels.inl (cmake/isa_kernels.cmake). Every lane does the
// double-precision operations of the scalar code in the same order, so every level gives
// the same bytes and the scalar build is the plain twin the vector ones are held to.
//
// Plain data only: the per-ISA translation units include this header, and no inline
// function built for a wider instruction set may reach the rest of the program.
#pragma once

#include <cstdint>

namespace shadowlab::izb {

// Arrays a kernel reads or writes a vector at a time hold kKernelPadding values past the
// last one it is given: the widest kernel's lanes (AVX-512, doubles).
inline constexpr int kKernelPadding = 8;

// ---- Stage 1: shadow segments -------------------------------------------------------------
// Receiving points (G-buffer P and N, widened from float) in structure-of-arrays form.
struct PointColumns {
    const double* x;
    const double* y;
    const double* z;
    const double* nx;
    const double* ny;
    const double* nz;
};
// Their segments: the origin P + offset N rounded to float (so exact here), and tFar.
struct SegmentColumns {
    double* x;
    double* y;
    double* z;
    double* tFar;
};
struct SegmentConstants {
    double light[4];          // homogeneous light (x, y, z, w), homogeneousLight()
    double sceneDiagonal;     // D of shadowRayOffset()
    double offsetPerScale;    // kShadowRayOffsetPerScale: shadowRayOffset() = it * max(max_k |P_k|, D)
};
using SegmentKernel = void (*)(const SegmentConstants& constants, const PointColumns& points, uint32_t count,
                               const SegmentColumns& segments);

// ---- Stage 6: the exact test --------------------------------------------------------------
// Receivers in list order (ListedReceivers, izb.h): segment origins (floats, as the
// reference's ray origins) and ends.
struct ReceiverColumns {
    const float* x;
    const float* y;
    const float* z;
    const double* tFar;
};
// One occluder and the light: the vertices x0 y0 z0 x1 ... z2, and the homogeneous light.
struct OccluderTriangle {
    double vertex[9];
    double light[4];
};
// Sets blocked[k] = 1 for every receiver k in [begin, end) whose segment the triangle meets;
// leaves the other bytes of `blocked` as they are.
using OcclusionKernel = void (*)(const OccluderTriangle& triangle, const ReceiverColumns& receivers, uint32_t begin,
                                 uint32_t end, uint8_t* blocked);

// A receiver whose segment meets a cut-out triangle, and where: the point
// (1 - u - v) A + u B + v C of the triangle's plane, u and v rounded to float as the
// reference's Embree hit reports them (shadows/caster_transmission.h, solidAt).
struct SegmentHit {
    uint32_t receiver;
    float u, v;
};
// Writes to hits[0], hits[1], ... every receiver k in [begin, end) whose segment the
// triangle meets, in increasing k, and returns their number (at most end - begin).
using CrossingKernel = uint32_t (*)(const OccluderTriangle& triangle, const ReceiverColumns& receivers, uint32_t begin,
                                    uint32_t end, SegmentHit* hits);

// One segment, origin + t * towardsLight for t in [0, tFar], against one triangle (its
// vertices' x, y, z): the occlusion kernel's test on a single receiver, whose scalar build is
// the twin the tests hold every level to (izb.h, segmentBlocked).
using SegmentTest = bool (*)(const double (&origin)[3], const double (&towardsLight)[3], double tFar,
                             const double (&triangle)[9]);

struct Kernels {
    SegmentKernel segments;
    OcclusionKernel occlusion;
    CrossingKernel crossings;
    SegmentTest segmentBlocked;
};
Kernels kernelsScalar();
Kernels kernelsAvx2();
Kernels kernelsAvx512();

}  // namespace shadowlab::izb
