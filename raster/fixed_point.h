// Fixed-point window coordinates and the ranges the rasterizer guarantees.
//
// Vertices are snapped once, in setup, to 1/256 pixel (kSubpixelBits = 8). Every coverage
// decision after that is made on integers, so it is exact and the same on every path.
//
// Range argument (written down as llvmpipe does in lp_rast_tri_tmp.h):
//  * the viewport is at most kMaxViewport = 8192 pixels on a side;
//  * triangles reaching further than kGuardBandPixels = 8192 pixels from the viewport centre
//    are clipped against guard-band planes in clip space (raster/clip.cpp), so every snapped
//    coordinate lies within +-(4096 + 8192) pixels < 2^14 pixels = 2^22 sub-pixel units;
//  * an edge coefficient (a difference of two coordinates) is then below 2^23, and the
//    edge constant (a 2x2 determinant) below 2^46: integers that setup's double lanes
//    hold exactly (setup_triangles.inl);
//  * per pixel, the edge function is evaluated in pixel units, e = A*i + B*j + c (see
//    setup_triangles.inl for the exact reduction). An edge is tested per pixel only inside a tile
//    where it takes both signs over the triangle's pixels, so anywhere in that 64x64 tile
//    (its origin, its blocks' corners, its pixels) e stays within twice its variation
//    across the tile: |e| <= 2 * 63 * (|A| + |B|) < 2^31. The per-pixel tests therefore run
//    in int32 lanes.
//    Edges that do not cross a tile are accepted or rejected for the whole tile first.
#pragma once

#include <cstdint>

namespace shadowlab::raster {

inline constexpr int kSubpixelBits = 8;
inline constexpr int32_t kSubpixelOne = 1 << kSubpixelBits;
inline constexpr int32_t kSubpixelHalf = kSubpixelOne / 2;

inline constexpr int kMaxViewport = 8192;
inline constexpr double kGuardBandPixels = 8192.0;

inline constexpr int kTileShift = 6;                 // 64x64-pixel tiles are the unit of
inline constexpr int kTileSize = 1 << kTileShift;    // binning and of thread ownership
inline constexpr int kBlockShift = 3;                // 8x8-pixel blocks are the unit of the
inline constexpr int kBlockSize = 1 << kBlockShift;  // coarse test and of buffer layout
inline constexpr int kBlocksPerTileSide = kTileSize / kBlockSize;
inline constexpr int kPixelsPerBlock = kBlockSize * kBlockSize;
inline constexpr int kPixelsPerTile = kTileSize * kTileSize;

}  // namespace shadowlab::raster
