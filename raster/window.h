// The viewport transform: perspective divide, window coordinates (row 0 at the top,
// conventions.md) and snapping to the fixed-point grid (fixed_point.h). Both the vertex
// stage and the clipping path call this one function, so a vertex gets the same bits
// whichever way it reaches setup.
#pragma once

#include <cmath>
#include <cstdint>

#include <glm/glm.hpp>

#include "raster/fixed_point.h"

namespace shadowlab::raster {

struct WindowVertex {
    int32_t x, y;        // snapped, sub-pixel units
    double z;            // window depth, OpenGL depth range [0, 1]
    double inverseW;     // for perspective-correct varyings
};

// `clip` must have w > 0 and lie inside the guard band (clip.h).
inline WindowVertex toWindow(const glm::vec4& clip, int width, int height) {
    const double inverseW = 1.0 / double(clip.w);
    const double x = (double(clip.x) * inverseW + 1.0) * 0.5 * width;
    const double y = (1.0 - double(clip.y) * inverseW) * 0.5 * height;
    const double z = (double(clip.z) * inverseW + 1.0) * 0.5;
    return {int32_t(std::nearbyint(x * kSubpixelOne)), int32_t(std::nearbyint(y * kSubpixelOne)), z, inverseW};
}

}  // namespace shadowlab::raster
