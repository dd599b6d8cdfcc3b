// Triangle setup as the front end drives it: triangles are queued in submission order, set
// up kSetupBatchSize at a time by the kernel of the draw's SIMD level (setup_kernel.h,
// setup_triangles.inl: culling, snapping's consequences, edge functions, planes), and the
// survivors appended to the chunk the front end is filling.
#pragma once

#include <cstdint>

#include "raster/bin.h"
#include "raster/pipeline_state.h"
#include "raster/setup_kernel.h"
#include "raster/window.h"

namespace shadowlab::raster {

// A triangle corner after the viewport transform, with its varyings (null when none).
struct SetupVertex {
    WindowVertex window;
    const float* varyings;
};

// What a triangle inherits from the primitive it came from (several, when clipping made a
// fan): its id, and the largest window depth of the whole primitive, which sets the
// polygon offset's r (OpenGL 4.6 section 14.6.5 takes it per primitive).
struct Primitive {
    uint32_t id;
    double maxDepth;
};

// Varying planes are set up only for a draw that interpolates them.
SetupConstants setupConstants(int width, int height, const PipelineState& state, int varyingCount);

class SetupQueue {
public:
    SetupQueue(SetupKernel kernel, const SetupConstants& constants, SetupChunk& chunk);
    void push(const SetupVertex (&corners)[3], const Primitive& primitive);
    // Sets up the queued triangles; call before reading the chunk.
    void flush();

private:
    SetupKernel kernel_;
    SetupConstants constants_;
    SetupChunk& chunk_;
    SetupBatch batch_{};   // zeroed once, so lanes past a short batch's count hold numbers
    SetupOutput output_;
};

}  // namespace shadowlab::raster
