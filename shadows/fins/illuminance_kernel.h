// The illuminance buffer's per-pixel arithmetic (illuminance_buffer.h) as two vector
// kernels, written once (illuminance_kernel.inl) against the SIMD types of raster/simd/ and
// compiled for scalar, AVX2 and AVX-512 (cmake/isa_kernels.cmake):
//
//   place        each pixel's receiver in the layer's maps: its texel, its depth at the
//                texel's centre and L_r, its distance from the light's plane;
//   illuminate   from the maps' values at those texels, the layer's local illuminance
//                (the hard test, the refined fin weights of eqs. 2 to 5) and I = min(I, local).
//
// Between them the caller reads the maps at the texels (DepthMap::at), outside the
// per-ISA code. Every lane does the double operations of the plain expressions in their
// order (glm's matrix product, eqs. 2 to 5 and the fall-off as finTerm in
// tests/shadows/fins/test_illuminance_kernel.cpp writes them, lightDistanceOfDepth), so every
// level gives the same bytes and the scalar build is the twin the others are held to.
//
// Plain data only: the per-ISA translation units include this header, and no inline
// function built for a wider instruction set may reach the rest of the program.
#pragma once

#include <cstddef>
#include <cstdint>

namespace shadowlab::fins {

// The hard map's bias is slope-scaled (applied when it was drawn), so a receiver is P
// projected as it is: MapReceiver with no offset, slope or tolerance.
struct PlaceConstants {
    double texelFromWorld[16];    // column-major, as glm
    double lastTexel;             // size - 1: texels are clamped to the map
    double lightCentre[3];        // the disk's plane: L(p) = (p - centre) . normal
    double lightNormal[3];
};

// Per pixel, what place writes and illuminate reads.
struct PlacedColumns {
    double* x;                    // the texel, an integer in [0, size - 1]
    double* y;
    double* depthAtCentre;        // the receiver's window depth at the texel's centre
    double* lightDistance;        // L_r
};

// The maps' values at each pixel's texel, widened from float: the hard map's depth, and
// each penumbra map's fin depth (1 where no fin covers) and weight s_0. inner* are null
// for outer-only methods.
struct TexelColumns {
    const double* hardDepth;
    const double* innerDepth;
    const double* innerWeight;
    const double* outerDepth;
    const double* outerWeight;
};

struct IlluminateConstants {
    double depthRow22, depthRow32;   // the view's clipFromView[2][2] and [3][2] (lightDistanceOfDepth)
    double referenceDistance;        // L_0
    double edgeWeight;               // e
    bool bernstein;                  // Falloff::Bernstein, else linear
};

// positions: x, y, z floats per pixel (the G-buffer's P).
using PlaceKernel = void (*)(const PlaceConstants& c, const float* positions, uint32_t count, const PlacedColumns& out);
// values: I per pixel, lowered to min(I, local).
using IlluminateKernel = void (*)(const IlluminateConstants& c, const PlacedColumns& placed, const TexelColumns& texels,
                                  uint32_t count, float* values);

struct IlluminanceKernels {
    int width;                    // pixels a vector step takes; counts are multiples of it
    PlaceKernel place;
    IlluminateKernel illuminate;
};
IlluminanceKernels illuminanceKernelsScalar();
IlluminanceKernels illuminanceKernelsAvx2();
IlluminanceKernels illuminanceKernelsAvx512();

}  // namespace shadowlab::fins
