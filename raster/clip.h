// Homogeneous clipping (Sutherland-Hodgman in clip space, OpenGL's -w <= z <= w).
//
// The near plane is always clipped, so every vertex that reaches the perspective divide
// has w > 0. The far plane is optional: an infinite far projection (shadow volumes) turns
// it off. Instead of clipping at the viewport sides, a guard band lets triangles extend up
// to kGuardBandPixels beyond the viewport centre; only triangles reaching past that are
// clipped at the guard band, which keeps snapped coordinates in the range fixed_point.h
// proves safe. Anything outside the viewport is then simply never rasterized.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "raster/triangle_setup.h"

namespace shadowlab::raster {

// In exact arithmetic a triangle clipped by six planes keeps at most 3 + 6 vertices; in
// floating point a polygon lying almost in a plane can cross it more often. Clipping
// drops a polygon that would outgrow this capacity (only such slivers can).
inline constexpr int kMaxClippedVertices = 16;

struct ClipVertex {
    glm::vec4 position;
    float varyings[kMaxVaryings];
};

struct ClipVolume {
    bool clipFar = true;
    float guardX = 1.0f, guardY = 1.0f;   // guard band half-extent in NDC units (>= 1)
};

ClipVolume clipVolumeFor(int width, int height, bool clipFar);

// Bit k set: the vertex is outside clipping plane k (near, far, guard -x, +x, -y, +y).
uint32_t clipOutcode(const glm::vec4& p, const ClipVolume& volume);
// Bit k set: the vertex is outside viewport plane k (-x, +x, -y, +y, near, far). A
// triangle whose three vertices share a bit cannot be seen.
uint32_t viewportOutcode(const glm::vec4& p, const ClipVolume& volume);

// Clips the convex polygon `polygon` (n vertices, room for kMaxClippedVertices) against
// the planes set in `outcodes`, in place; returns the new vertex count (0 when nothing is
// left, or when the polygon would outgrow kMaxClippedVertices).
int clipPolygon(ClipVertex* polygon, int n, uint32_t outcodes, const ClipVolume& volume, int varyingCount);

}  // namespace shadowlab::raster
