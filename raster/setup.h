// Triangle setup: perspective divide, viewport, snapping to fixed point, culling, the
// integer edge functions with the top-left rule, pixel bounds, and the depth and varying
// planes. Everything that decides coverage is integer; see fixed_point.h for the ranges.
#pragma once

#include <vector>

#include "raster/pipeline_state.h"
#include "raster/triangle_setup.h"
#include "raster/window.h"

namespace shadowlab::raster {

struct SetupContext {
    int width, height;
    const PipelineState* state;
    int varyingCount;
};

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

// Sets up one triangle. Returns false when it is culled, degenerate after snapping, or its
// pixel bounds hold no pixel centre (no pixel at all, in conservative mode). Its varying
// planes are appended to `planes`; `out.varyings` is left for the caller to point at them
// once `planes` stops growing.
bool setupTriangle(const SetupVertex (&corners)[3], const Primitive& primitive, const SetupContext& context,
                   TriangleSetup& out, std::vector<Plane>& planes);

}  // namespace shadowlab::raster
