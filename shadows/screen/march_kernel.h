// The screen-space march (screen_march.h) as a vector kernel: lanes are pixels of a row,
// each marching its own ray towards the light over the camera's G-buffer. Single-precision
// floats in structure-of-arrays vectors, written once (march_kernel.inl) against the SIMD
// types of raster/simd/ and compiled for scalar, AVX2 and AVX-512 (cmake/isa_kernels.cmake).
// Every lane does the float operations of the plain expressions (glm's dot, normalize,
// length and matrix product) in their order, so every level gives the same bits and the
// scalar build is the twin the others are held to; it is also the one the plotted march
// of a single pixel runs (march_plot.h): one implementation of the step.
//
// Plain data only: the per-ISA translation units include this header, and no inline
// function built for a wider instruction set may reach the rest of the program.
#pragma once

#include <cstddef>
#include <cstdint>

namespace shadowlab {

struct MarchConstants {
    float clipFromWorld[16];   // column-major, as glm
    float eye[3];
    float forward[3];          // the camera's unit axis: view depth = (p - eye) . forward
    float zNear;
    float pixelFootprint;      // a pixel's height at unit view depth, m per m
    int width, height;         // the G-buffer's, pixels
    bool directional;          // light: the direction towards it as given, else its position
    float light[3];
    float lengthM;             // MarchSettings
    int steps;
    float thicknessM;
};

// The surfaces the march reads at each sample's pixel q: component c (P.x, P.y, P.z, N.x,
// N.y, N.z) at surface[c][stride * q]. N is 0 where no surface covers q (the G-buffer's
// convention), so that a sample there meets no plane without a read of `hit`.
struct MarchSurfaces {
    const float* surface[6];
    int stride;
};

// The ends, numbered as MarchEnd (screen_march.h checks it).
enum MarchKernelEnd : int { kMarchLit, kMarchOccluded, kMarchLeftScreen };

// One run of pixels of a row, first..first + count - 1 in the G-buffer's order; count is a
// multiple of the kernel's width.
struct MarchRow {
    const uint8_t* active;     // 1 where the pixel has a surface the light reaches: its march runs
    int first;
    int count;
};

// mask: per pixel, the end of its march (MarchKernelEnd; Lit where not active), and V = 0
// where occluded, 1 elsewhere.
struct MarchMaskOut {
    uint8_t* end;
    float* visibility;
};

// trace: every sample of every step of each pixel's march, not stopping at the first
// occluded one: step s (from 1) of pixel n of the run at [(s - 1) * count + n]. samples:
// per pixel, the steps before the ray left the screen (those that hold a sample).
struct MarchTraceOut {
    float* distance;           // MarchSample's fields
    float* pixelX;
    float* pixelY;
    float* sampleDepth;
    float* bufferDepth;
    uint32_t* occluded;
    uint32_t* samples;
};

using MarchMaskKernel = void (*)(const MarchConstants&, const MarchSurfaces&, const MarchRow&, const MarchMaskOut&);
using MarchTraceKernel = void (*)(const MarchConstants&, const MarchSurfaces&, const MarchRow&, const MarchTraceOut&);

struct MarchKernels {
    int width;                 // pixels per vector
    MarchMaskKernel mask;
    MarchTraceKernel trace;
};

MarchKernels marchKernelsScalar();
MarchKernels marchKernelsAvx2();
MarchKernels marchKernelsAvx512();

}  // namespace shadowlab
