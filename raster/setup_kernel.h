// Triangle setup a batch at a time: the kernel (setup_triangles.inl) is written once against
// the SIMD types of raster/simd/ and compiled for scalar, AVX2 and AVX-512 in the per-ISA
// units (kernel_table.h), one triangle per double lane. Every integer it computes is exact
// in double, and every plane is the same double operations in the same order on every
// level, so the levels give the same TriangleSetup bytes and the scalar build is the twin.
//
// Plain data only: the per-ISA translation units include this header.
#pragma once

#include <cstdint>

#include "raster/pipeline_state.h"
#include "raster/triangle_setup.h"

namespace shadowlab::raster {

// Triangles per batch: a multiple of every level's double lanes (8 on AVX-512).
inline constexpr int kSetupBatchSize = 16;

// What setup needs of the draw.
struct SetupConstants {
    int width, height;                   // the framebuffer
    int windowX, windowY;                // its origin in the viewport (pipeline_state.h, ViewportWindow)
    int viewportWidth, viewportHeight;
    CullMode cull;
    bool conservative;
    PolygonOffset offset;
    int planeCount;   // varying planes per triangle: 0, or 1/w and each varying
};

// Up to kSetupBatchSize triangles in structure-of-arrays form; index [k][t] is corner k of
// triangle t. Window x and y are the snapped sub-pixel integers (exact in double).
struct SetupBatch {
    alignas(64) double x[3][kSetupBatchSize];
    alignas(64) double y[3][kSetupBatchSize];
    alignas(64) double z[3][kSetupBatchSize];
    alignas(64) double inverseW[3][kSetupBatchSize];
    alignas(64) double varyings[kMaxVaryings][3][kSetupBatchSize];   // as floats, widened
    // The largest window depth of the primitive each came from (the polygon offset's r).
    alignas(64) double maxDepth[kSetupBatchSize];
    uint32_t primitiveId[kSetupBatchSize];
    int count;
};

// The batch's triangles that survive culling, in batch order, each with its planes.
struct SetupOutput {
    TriangleSetup triangles[kSetupBatchSize];   // `varyings` left null
    Plane planes[kSetupBatchSize][1 + kMaxVaryings];
    int count;
};

using SetupKernel = void (*)(const SetupBatch& batch, const SetupConstants& constants, SetupOutput& out);

}  // namespace shadowlab::raster
