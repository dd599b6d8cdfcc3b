// The viewport transform: perspective divide, window coordinates (row 0 at the top,
// conventions.md) and snapping to the fixed-point grid (fixed_point.h). Both the vertex
// stage and the clipping path call this one function, so a vertex gets the same bits
// whichever way it reaches setup.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "raster/fixed_point.h"

namespace shadowlab::raster {

struct WindowVertex {
    int32_t x, y;        // snapped, sub-pixel units
    double z;            // window depth, OpenGL depth range [0, 1]
    double inverseW;     // for perspective-correct varyings
};

// x rounded to the nearest integer, ties to even, as std::nearbyint in the default rounding
// mode, for |x| < 2^51: adding 1.5 * 2^52 leaves a sum whose unit in the last place is 1, so
// the addition itself rounds. Inline, where nearbyint is a library call per coordinate
// (baseline x86-64 has no SSE4.1 round); the compiler may not fold the sum away
// (-fno-fast-math).
inline double roundToEven(double x) {
    constexpr double kShift = 0x1.8p52;
    return (x + kShift) - kShift;
}

// `clip` must have w > 0 and lie inside the guard band (clip.h), so every snapped coordinate
// is far below 2^51 (fixed_point.h: below 2^22).
inline WindowVertex toWindow(const glm::vec4& clip, int width, int height) {
    const double inverseW = 1.0 / double(clip.w);
    const double x = (double(clip.x) * inverseW + 1.0) * 0.5 * width;
    const double y = (1.0 - double(clip.y) * inverseW) * 0.5 * height;
    const double z = (double(clip.z) * inverseW + 1.0) * 0.5;
    return {int32_t(roundToEven(x * kSubpixelOne)), int32_t(roundToEven(y * kSubpixelOne)), z, inverseW};
}

}  // namespace shadowlab::raster
