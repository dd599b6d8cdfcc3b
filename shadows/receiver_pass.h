// The receiver pass every map-based technique makes over the camera's G-buffer: a call per
// pixel that sees a surface, rows in parallel; the call decides whether light can reach
// it (lightReaches(), shading/lights.h, or the facing test of one light sample). Each call
// writes only its own pixel's outputs, so the result is the same bytes for any thread
// count. The per-pixel work is a template argument, compiled in: no call through a
// pointer per pixel.
#pragma once

#include <cstddef>

#include <tbb/parallel_for.h>

#include "shading/gbuffer.h"

namespace shadowlab {

// perPixel(i, j, k) for every pixel k = (i, j) with hit = 1.
template <class PerPixel>
void forEachSurfacePixel(const GBuffer& g, PerPixel&& perPixel) {
    tbb::parallel_for(0, g.height, [&](int j) {
        for (int i = 0; i < g.width; ++i) {
            const size_t k = g.index(i, j);
            if (g.hit[k]) perPixel(i, j, k);
        }
    });
}

}  // namespace shadowlab
