// Helpers for the rasterizer tests: draw triangles given directly in window coordinates
// (x, y in pixels with row 0 at the top, z in [0, 1]) and an independent coverage oracle.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "raster/rasterizer.h"

namespace shadowlab::test {

// clip = M (x, y, z, 1) with x_ndc = 2x/W - 1, y_ndc = 1 - 2y/H, z_ndc = 2z - 1. For W and
// H powers of two and x, y multiples of 1/256, setup recovers x and y exactly.
inline glm::mat4 clipFromWindow(int width, int height) {
    glm::mat4 m(0.0f);
    m[0][0] = 2.0f / float(width);
    m[1][1] = -2.0f / float(height);
    m[2][2] = 2.0f;
    m[3] = glm::vec4(-1.0f, 1.0f, -1.0f, 1.0f);
    return m;
}

inline raster::DrawCall windowDraw(const raster::Framebuffer& fb, const std::vector<glm::vec3>& positions,
                                   const std::vector<glm::uvec3>& triangles) {
    raster::DrawCall call;
    call.vertices.positions = positions;
    call.triangles = triangles;
    call.clipFromObject = clipFromWindow(fb.width(), fb.height());
    return call;
}

// State that counts coverage in the stencil buffer: no culling, no depth test.
inline raster::PipelineState countingState() {
    raster::PipelineState s;
    s.cull = raster::CullMode::None;
    s.depth.test = false;
    s.stencil.enabled = true;
    s.stencil.front.depthPass = s.stencil.back.depthPass = raster::StencilOp::IncrementWrap;
    return s;
}

// Independent oracle: is the centre of pixel (i, j) covered by the triangle with snapped
// sub-pixel vertices a, b, c? Written from the definitions (inside, or on a top or left
// edge), not from the rasterizer's edge-bias formulation.
inline bool oracleCovers(const glm::i64vec2 v[3], int i, int j) {
    const int64_t px = int64_t(i) * 256 + 128, py = int64_t(j) * 256 + 128;
    const int64_t area = (v[1].x - v[0].x) * (v[2].y - v[0].y) - (v[2].x - v[0].x) * (v[1].y - v[0].y);
    if (area == 0) return false;
    for (int k = 0; k < 3; ++k) {
        const glm::i64vec2 a = v[k], b = v[(k + 1) % 3], c = v[(k + 2) % 3];
        const int64_t side = (b.x - a.x) * (py - a.y) - (b.y - a.y) * (px - a.x);
        const int64_t sideOfC = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
        if (side != 0) {
            if ((side > 0) != (sideOfC > 0)) return false;
            continue;
        }
        // On the edge's line: covered only for a top edge (horizontal, triangle below it,
        // y grows downwards) or a left edge (the triangle lies to the right of it).
        const bool top = a.y == b.y && c.y > a.y;
        const int64_t rightOfEdge = (c.x - a.x) * (b.y - a.y) - (c.y - a.y) * (b.x - a.x);   // times (b.y - a.y)
        const bool left = a.y != b.y && ((rightOfEdge > 0) == (b.y - a.y > 0));
        if (!top && !left) return false;
    }
    return true;
}

// The SIMD levels this CPU runs (tests run each kernel they can).
inline std::vector<raster::SimdLevel> supportedLevels() {
    std::vector<raster::SimdLevel> levels;
    for (raster::SimdLevel l : {raster::SimdLevel::Scalar, raster::SimdLevel::Avx2, raster::SimdLevel::Avx512}) {
        if (raster::simdLevelSupported(l)) levels.push_back(l);
    }
    return levels;
}

inline glm::i64vec2 snap(const glm::vec3& p) {
    return {int64_t(std::nearbyint(double(p.x) * 256.0)), int64_t(std::nearbyint(double(p.y) * 256.0))};
}

}  // namespace shadowlab::test
