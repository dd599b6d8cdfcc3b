// What triangle setup (setup_triangles.inl) hands to the tile kernels: integer edge functions,
// the pixel bounds, and float planes for depth and varyings. Plain data only, because
// the per-ISA kernels (tile_raster.inl) include it.
#pragma once

#include <cstddef>
#include <cstdint>

#include "raster/fixed_point.h"
#include "raster/pipeline_state.h"

namespace shadowlab::raster {

// Values a vertex carries besides its position, interpolated perspective-correctly.
inline constexpr int kMaxVaryings = 8;

// An attribute that varies affinely across the screen: value at the centre of the
// reference pixel (TriangleSetup::refX, refY) and its change per pixel step in x and in y.
struct Plane {
    float atRef, perX, perY;
};

// Per triangle, after clipping and snapping. The edge function of edge k, in pixel units,
//   e_k(i, j) = edgeA[k] * i + edgeB[k] * j + edgeC[k],
// is >= 0 exactly when pixel (i, j) is covered with respect to that edge: the top-left
// rule (or, in conservative mode, the pixel-square test) is already folded into edgeC.
struct TriangleSetup {
    int32_t edgeA[3], edgeB[3];
    int64_t edgeC[3];
    int32_t minX, minY, maxX, maxY;   // pixel bounds, half-open, inside the framebuffer
    // The planes' reference pixel, framebuffer coordinates: the bounds' first pixel clamped
    // to the viewport, not to the framebuffer, so that every window of a viewport evaluates
    // a plane from the same pixel (pipeline_state.h, ViewportWindow). It may lie outside
    // the framebuffer; the offsets from it stay below 2^15, exact in float.
    int32_t refX, refY;
    Plane depth;                      // window depth, polygon offset included
    const Plane* varyings;            // 1/w first, then each varying divided by w
    uint32_t primitiveId;
    bool frontFacing;
};

// A fragment of FragmentOutput::FragmentList: where it is (the pixel's storage index,
// FramebufferView), its window depth and its triangle.
struct Fragment {
    uint32_t pixel;
    float depth;
    uint32_t primitiveId;
};

// One tile's list of fragments: a plain array the tile's one task appends to, which calls
// `grow` (defined with the framebuffer, in baseline code) when it is full. No member
// functions: the per-ISA kernels must not share inline code compiled for another ISA.
struct FragmentSink {
    Fragment* data;
    uint32_t size, capacity;
    void (*grow)(FragmentSink& sink);
};

// The buffers of a framebuffer as the kernels see them. Every buffer is stored
// block-linear: 64x64 tiles in row-major order, inside a tile 8x8 blocks in row-major
// order, inside a block pixels in row-major order. One 8x8 block is then 64 consecutive
// values, so a vector of 1, 8 or 16 lanes is always one contiguous load.
struct FramebufferView {
    int width, height, tilesX;
    float* depth;
    uint8_t* stencil;         // null when the framebuffer has none
    float* color[4];          // R, G, B, A planes; null when absent
    uint32_t* primitiveId;    // null when absent
    FragmentSink* fragments;  // one per tile; null when absent
};

struct DrawConstants {
    PipelineState state;
    float constantColor[4];
    int varyingCount;
};

}  // namespace shadowlab::raster
