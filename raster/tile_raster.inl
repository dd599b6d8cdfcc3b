// Per-tile rasterization: coverage, depth, stencil and the fragment's output for one
// triangle inside one 64x64 tile. Written once against the SIMD interface of
// simd/simd_scalar.h and included by the per-ISA units (cmake/isa_kernels.cmake), each inside
// its own namespace with `namespace simd = <that ISA's types>`, so every instruction set
// runs the same algorithm (Masked Occlusion Culling's "one body, one front file per ISA").
//
// Order of work (hierarchical, as llvmpipe's 64 -> 16 -> 4 descent):
//  1. the tile: edges that do not cross the triangle's pixel bounds inside the tile accept
//     or reject it whole (int64); the others are kept, now provably in int32 range;
//  2. each 8x8 block: the kept edges are tested at the block's extreme corners, so blocks
//     are skipped, or drop edges that cover them entirely;
//  3. each vector of pixels (1, 8 or 16 lanes of a block): the remaining edges, then the
//     stencil and depth tests of OpenGL 4.6 section 17.3, then the fragment's output.
// No float decides coverage; every float operation is the same per lane on every path.

using simd::F32;
using simd::I32;
using simd::Mask;

inline int minInt(int a, int b) { return a < b ? a : b; }
inline int maxInt(int a, int b) { return a > b ? a : b; }
inline int32_t negativePart(int32_t a) { return a < 0 ? a : 0; }
inline int32_t positivePart(int32_t a) { return a > 0 ? a : 0; }

// a FUNC b, as the depth test (fragment FUNC stored) reads it.
inline Mask compare(CompareFunc func, F32 a, F32 b) {
    switch (func) {
        case CompareFunc::Never: return simd::noLanes();
        case CompareFunc::Less: return simd::cmpLt(a, b);
        case CompareFunc::Equal: return simd::cmpEq(a, b);
        case CompareFunc::LessEqual: return simd::cmpLe(a, b);
        case CompareFunc::Greater: return simd::cmpLt(b, a);
        case CompareFunc::NotEqual: return simd::cmpNe(a, b);
        case CompareFunc::GreaterEqual: return simd::cmpLe(b, a);
        case CompareFunc::Always: break;
    }
    return simd::allLanes();
}

// a FUNC b on integers, as the stencil test (masked reference FUNC masked stored) reads it.
inline Mask compare(CompareFunc func, I32 a, I32 b) {
    switch (func) {
        case CompareFunc::Never: return simd::noLanes();
        case CompareFunc::Less: return simd::cmpGt(b, a);
        case CompareFunc::Equal: return simd::cmpEq(a, b);
        case CompareFunc::LessEqual: return !simd::cmpGt(a, b);
        case CompareFunc::Greater: return simd::cmpGt(a, b);
        case CompareFunc::NotEqual: return !simd::cmpEq(a, b);
        case CompareFunc::GreaterEqual: return !simd::cmpGt(b, a);
        case CompareFunc::Always: break;
    }
    return simd::allLanes();
}

// OpenGL 4.6 table 17.3; values are 8-bit, so wrapping is "& 255".
inline I32 applyStencilOp(StencilOp op, I32 s, int32_t reference) {
    const I32 one = simd::splat(int32_t(1)), byteMask = simd::splat(int32_t(255));
    switch (op) {
        case StencilOp::Keep: break;
        case StencilOp::Zero: return simd::splat(int32_t(0));
        case StencilOp::Replace: return simd::splat(reference);
        case StencilOp::Increment: return simd::select(simd::cmpGt(byteMask, s), s + one, s);
        case StencilOp::Decrement: return simd::select(simd::cmpGt(s, simd::splat(int32_t(0))), s - one, s);
        case StencilOp::IncrementWrap: return (s + one) & byteMask;
        case StencilOp::DecrementWrap: return (s - one) & byteMask;
        case StencilOp::Invert: return s ^ byteMask;
    }
    return s;
}

inline F32 blendFactor(BlendFactor f, F32 srcColor, F32 dstColor, F32 srcAlpha, F32 dstAlpha) {
    const F32 one = simd::splat(1.0f);
    switch (f) {
        case BlendFactor::Zero: return simd::splat(0.0f);
        case BlendFactor::One: break;
        case BlendFactor::SrcColor: return srcColor;
        case BlendFactor::OneMinusSrcColor: return one - srcColor;
        case BlendFactor::DstColor: return dstColor;
        case BlendFactor::OneMinusDstColor: return one - dstColor;
        case BlendFactor::SrcAlpha: return srcAlpha;
        case BlendFactor::OneMinusSrcAlpha: return one - srcAlpha;
        case BlendFactor::DstAlpha: return dstAlpha;
        case BlendFactor::OneMinusDstAlpha: return one - dstAlpha;
    }
    return one;
}

inline F32 blend(const BlendState& b, F32 src, F32 dst, F32 srcAlpha, F32 dstAlpha) {
    switch (b.equation) {
        case BlendEquation::Min: return simd::min(src, dst);
        case BlendEquation::Max: return simd::max(src, dst);
        default: break;
    }
    const F32 s = src * blendFactor(b.srcFactor, src, dst, srcAlpha, dstAlpha);
    const F32 d = dst * blendFactor(b.dstFactor, src, dst, srcAlpha, dstAlpha);
    if (b.equation == BlendEquation::Subtract) return s - d;
    if (b.equation == BlendEquation::ReverseSubtract) return d - s;
    return s + d;
}

// One vector of fragments of one triangle: lane k is pixel (x[k], y[k]), stored at
// buffer index `offset + k`.
struct FragmentVector {
    Mask covered;
    I32 x, y;
    size_t offset;
};

inline F32 evaluatePlane(const Plane& p, F32 dx, F32 dy) {
    return simd::splat(p.atRef) + simd::splat(p.perX) * dx + simd::splat(p.perY) * dy;
}

// Stencil test and update (OpenGL 4.6 section 17.3.3); returns the lanes that pass both
// the stencil and the depth test.
inline Mask stencilTest(const TriangleSetup& tri, const StencilState& st, const FragmentVector& f,
                        Mask depthPass, uint8_t* stencilBuffer) {
    const StencilFace& face = tri.frontFacing ? st.front : st.back;
    uint8_t* at = stencilBuffer + f.offset;
    const I32 stored = simd::loadU8(at);
    const I32 compareMask = simd::splat(int32_t(face.compareMask));
    const I32 reference = simd::splat(int32_t(face.reference));
    const Mask stencilPass = compare(face.func, reference & compareMask, stored & compareMask);
    const I32 next = simd::select(!stencilPass, applyStencilOp(face.stencilFail, stored, face.reference),
                     simd::select(!depthPass, applyStencilOp(face.depthFail, stored, face.reference),
                                  applyStencilOp(face.depthPass, stored, face.reference)));
    const I32 writeMask = simd::splat(int32_t(face.writeMask));
    const I32 keptBits = simd::splat(int32_t(~face.writeMask & 0xff));
    simd::storeU8(at, simd::select(f.covered, (stored & keptBits) | (next & writeMask), stored));
    return f.covered & stencilPass & depthPass;
}

template <FragmentOutput kOutput>
inline void writeColor(const TriangleSetup& tri, const DrawConstants& draw, const FramebufferView& fb,
                       const FragmentVector& f, Mask pass, F32 dx, F32 dy) {
    F32 src[4] = {simd::splat(draw.constantColor[0]), simd::splat(draw.constantColor[1]),
                  simd::splat(draw.constantColor[2]), simd::splat(draw.constantColor[3])};
    if constexpr (kOutput == FragmentOutput::VaryingColor) {
        // Perspective-correct: interpolate a/w and 1/w affinely, then divide.
        const F32 inverseW = evaluatePlane(tri.varyings[0], dx, dy);
        const int channels = minInt(draw.varyingCount, 4);
        for (int c = 0; c < channels; ++c) src[c] = evaluatePlane(tri.varyings[1 + c], dx, dy) / inverseW;
    }
    const F32 dstAlpha = fb.color[3] ? simd::load(fb.color[3] + f.offset) : simd::splat(1.0f);
    const BlendState& b = draw.state.blend;
    for (int c = 0; c < 4; ++c) {
        if (!fb.color[c] || !(draw.state.colorWriteMask & (1u << c))) continue;
        float* at = fb.color[c] + f.offset;
        const F32 dst = c == 3 ? dstAlpha : simd::load(at);
        const F32 out = b.enabled ? blend(b, src[c], dst, src[3], dstAlpha) : src[c];
        simd::store(at, simd::select(pass, out, dst));
    }
}

// The passing lanes, in lane order, onto the list of the tile they lie in.
inline void appendFragments(const TriangleSetup& tri, const FramebufferView& fb, const FragmentVector& f, Mask pass,
                            F32 z) {
    uint32_t passes[simd::kWidth];
    float depths[simd::kWidth];
    simd::store(passes, simd::select(pass, simd::splat(int32_t(1)), simd::splat(int32_t(0))));
    simd::store(depths, z);
    FragmentSink& sink = fb.fragments[f.offset / kPixelsPerTile];
    for (int k = 0; k < simd::kWidth; ++k) {
        if (!passes[k]) continue;
        if (sink.size == sink.capacity) sink.grow(sink);
        sink.data[sink.size++] = {uint32_t(f.offset) + uint32_t(k), depths[k], tri.primitiveId};
    }
}

// The lanes whose alpha reaches the cutoff (pipeline_state.h, AlphaTest): u and v
// perspective-correct from varyings 0 and 1, read by the one texel rule (nearest_texel.inl).
inline Mask alphaTestPasses(const TriangleSetup& tri, const AlphaTest& test, F32 dx, F32 dy) {
    const F32 inverseW = evaluatePlane(tri.varyings[0], dx, dy);
    const F32 u = evaluatePlane(tri.varyings[1], dx, dy) / inverseW;
    const F32 v = evaluatePlane(tri.varyings[2], dx, dy) / inverseW;
    const F32 alpha = simd::gather(test.alpha, nearestTexelIndex(test.width, test.height, test.wrap, u, v));
    return !simd::cmpLt(alpha, simd::splat(test.cutoff));
}

template <FragmentOutput kOutput, bool kStencil, bool kAlphaTest>
inline void shadeFragments(const TriangleSetup& tri, const DrawConstants& draw, const FramebufferView& fb,
                           FragmentVector f) {
    // Offsets from the setup's reference pixel are small integers, exact in float.
    const F32 dx = simd::toFloat(f.x - simd::splat(tri.refX));
    const F32 dy = simd::toFloat(f.y - simd::splat(tri.refY));
    if constexpr (kAlphaTest) {
        f.covered = f.covered & alphaTestPasses(tri, draw.state.alphaTest, dx, dy);
        if (!simd::any(f.covered)) return;
    }
    // Window depth is clamped to [0, 1] after the polygon offset, as OpenGL does.
    const F32 z = simd::min(simd::max(evaluatePlane(tri.depth, dx, dy), simd::splat(0.0f)), simd::splat(1.0f));
    const DepthState& ds = draw.state.depth;
    float* depthAt = fb.depth + f.offset;
    const F32 storedZ = simd::load(depthAt);
    const Mask depthPass = ds.test ? compare(ds.func, z, storedZ) : simd::allLanes();
    Mask pass = f.covered & depthPass;
    if constexpr (kStencil) pass = stencilTest(tri, draw.state.stencil, f, depthPass, fb.stencil);
    if (!simd::any(pass)) return;
    if (ds.test && ds.write) simd::store(depthAt, simd::select(pass, z, storedZ));
    if constexpr (kOutput == FragmentOutput::PrimitiveId) {
        uint32_t* at = fb.primitiveId + f.offset;
        simd::store(at, simd::select(pass, simd::splat(int32_t(tri.primitiveId)), simd::load(at)));
    } else if constexpr (kOutput == FragmentOutput::FragmentList) {
        appendFragments(tri, fb, f, pass, z);
    } else if constexpr (kOutput != FragmentOutput::DepthOnly) {
        writeColor<kOutput>(tri, draw, fb, f, pass, dx, dy);
    }
}

// An edge that crosses the current tile, in int32: A, B, its value at the tile's origin,
// and A * x + B * y for the pixels of every vector of a block, relative to the block's
// origin (so a pixel's edge value is one add: the block's value plus the lane offset).
struct CrossingEdge {
    int32_t a, b, atTile;
    I32 laneOffset[kPixelsPerBlock / simd::kWidth];
};

struct PixelRect {
    int x0, y0, x1, y1;   // half-open
};

// Lane k of vector v of a block is the block's pixel v * W + k (row-major, 8 per row).
inline I32 blockLaneX(int v) { return (simd::splat(int32_t(v * simd::kWidth)) + simd::laneIndex()) & simd::splat(int32_t(kBlockSize - 1)); }
inline I32 blockLaneY(int v) { return simd::shiftRight<kBlockShift>(simd::splat(int32_t(v * simd::kWidth)) + simd::laneIndex()); }

// The vectors of a block that hold its rows [rowFirst, rowEnd): a triangle a row or two
// high (most of a dense mesh's) pays only for the vectors its rows lie in.
struct VectorRange {
    int first, end;
};
inline VectorRange vectorsOfRows(int rowFirst, int rowEnd) {
    return {rowFirst * kBlockSize / simd::kWidth, (rowEnd * kBlockSize + simd::kWidth - 1) / simd::kWidth};
}

inline Mask insideRect(I32 x, I32 y, const PixelRect& r) {
    return simd::cmpGt(x, simd::splat(int32_t(r.x0 - 1))) & simd::cmpGt(simd::splat(int32_t(r.x1)), x) &
           simd::cmpGt(y, simd::splat(int32_t(r.y0 - 1))) & simd::cmpGt(simd::splat(int32_t(r.y1)), y);
}

// One triangle in one tile: what every 8x8 block of it shares.
struct TileTriangle {
    const TriangleSetup& tri;
    const DrawConstants& draw;
    const FramebufferView& fb;
    const CrossingEdge* edges;   // the triangle's edges that cross the tile
    int edgeCount;
    int tileX, tileY;            // the tile's first pixel
    PixelRect region;            // the triangle's pixel bounds clipped to the tile
};

// Rasterizes the block at (blockX, blockY), whose pixels start at blockOffset in the
// block-linear buffers, and returns the number of fragments it covered.
template <FragmentOutput kOutput, bool kStencil, bool kAlphaTest>
uint64_t rasterizeBlock(const TileTriangle& t, int blockX, int blockY, size_t blockOffset) {
    // Coarse test: the extreme corners of the 8x8 block decide reject, accept or test.
    const CrossingEdge* edges[3];
    int32_t atBlock[3];
    int edgeCount = 0;
    constexpr int32_t kLast = kBlockSize - 1;
    for (int k = 0; k < t.edgeCount; ++k) {
        const CrossingEdge& e = t.edges[k];
        const int32_t value = e.atTile + e.a * (blockX - t.tileX) + e.b * (blockY - t.tileY);
        const int32_t highest = value + positivePart(e.a) * kLast + positivePart(e.b) * kLast;
        const int32_t lowest = value + negativePart(e.a) * kLast + negativePart(e.b) * kLast;
        if (highest < 0) return 0;
        if (lowest < 0) edges[edgeCount] = &e, atBlock[edgeCount++] = value;
    }
    const PixelRect& region = t.region;
    const bool blockInsideRegion = blockX >= region.x0 && blockX + kBlockSize <= region.x1 &&
                                   blockY >= region.y0 && blockY + kBlockSize <= region.y1;
    const VectorRange rows = vectorsOfRows(maxInt(region.y0 - blockY, 0), minInt(region.y1 - blockY, kBlockSize));
    const I32 minusOne = simd::splat(int32_t(-1));
    uint64_t fragments = 0;
    for (int v = rows.first; v < rows.end; ++v) {
        Mask covered = simd::allLanes();
        for (int k = 0; k < edgeCount; ++k) {
            covered = covered & simd::cmpGt(simd::splat(atBlock[k]) + edges[k]->laneOffset[v], minusOne);
        }
        const I32 x = simd::splat(int32_t(blockX)) + blockLaneX(v), y = simd::splat(int32_t(blockY)) + blockLaneY(v);
        if (!blockInsideRegion) covered = covered & insideRect(x, y, region);
        if (!simd::any(covered)) continue;
        fragments += uint64_t(simd::countLanes(covered));
        shadeFragments<kOutput, kStencil, kAlphaTest>(t.tri, t.draw, t.fb,
                                                      {covered, x, y, blockOffset + size_t(v * simd::kWidth)});
    }
    return fragments;
}

template <FragmentOutput kOutput, bool kStencil, bool kAlphaTest>
void rasterizeTriangleInTile(const TriangleSetup& tri, const Tile& tile, const DrawConstants& draw,
                             const FramebufferView& fb, uint64_t& fragments) {
    const int tileX = tile.x, tileY = tile.y;
    const PixelRect region = {maxInt(tri.minX, tileX), maxInt(tri.minY, tileY),
                              minInt(tri.maxX, tileX + kTileSize), minInt(tri.maxY, tileY + kTileSize)};
    if (region.x0 >= region.x1 || region.y0 >= region.y1) return;

    // The lane offsets of the vectors the blocks will test: within one row of blocks, the
    // vectors of the region's rows (rasterizeBlock tests no others).
    const int blockRowY = region.y0 & ~(kBlockSize - 1);
    const VectorRange vectors = region.y1 - blockRowY <= kBlockSize ? vectorsOfRows(region.y0 - blockRowY, region.y1 - blockRowY)
                                                                    : vectorsOfRows(0, kBlockSize);
    // Tile test in int64 over the region's extreme corners (fixed_point.h, range argument).
    CrossingEdge edges[3];
    int edgeCount = 0;
    for (int k = 0; k < 3; ++k) {
        const int64_t a = tri.edgeA[k], b = tri.edgeB[k], c = tri.edgeC[k];
        const int64_t lowest = c + a * (a > 0 ? region.x0 : region.x1 - 1) + b * (b > 0 ? region.y0 : region.y1 - 1);
        const int64_t highest = c + a * (a > 0 ? region.x1 - 1 : region.x0) + b * (b > 0 ? region.y1 - 1 : region.y0);
        if (highest < 0) return;
        if (lowest >= 0) continue;
        CrossingEdge& e = edges[edgeCount++];
        e.a = int32_t(a), e.b = int32_t(b), e.atTile = int32_t(c + a * tileX + b * tileY);
        for (int v = vectors.first; v < vectors.end; ++v) {
            e.laneOffset[v] = simd::splat(e.a) * blockLaneX(v) + simd::splat(e.b) * blockLaneY(v);
        }
    }

    const TileTriangle triangle{tri, draw, fb, edges, edgeCount, tileX, tileY, region};
    const size_t tileOffset = size_t(tile.index) * kPixelsPerTile;
    for (int blockY = region.y0 & ~(kBlockSize - 1); blockY < region.y1; blockY += kBlockSize) {
        for (int blockX = region.x0 & ~(kBlockSize - 1); blockX < region.x1; blockX += kBlockSize) {
            const size_t blockIndex = size_t(((blockY - tileY) >> kBlockShift) * kBlocksPerTileSide +
                                             ((blockX - tileX) >> kBlockShift));
            fragments += rasterizeBlock<kOutput, kStencil, kAlphaTest>(triangle, blockX, blockY,
                                                           tileOffset + blockIndex * kPixelsPerBlock);
        }
    }
}

// The level's table: setup (setup_triangles.inl, included before this file) and the tiles,
// by fragment output, then stencil use, then alpha test. Plain arrays: a library type's
// inline functions instantiated here would be compiled for this ISA and could be shared.
template <FragmentOutput kOutput, bool kStencil, bool kAlphaTest>
constexpr TileKernel tiles = &rasterizeTriangleInTile<kOutput, kStencil, kAlphaTest>;

inline const RasterKernels& kernels() {
    using O = FragmentOutput;
    static const RasterKernels table = {&setupTriangles, {
        {{tiles<O::DepthOnly, false, false>, tiles<O::DepthOnly, false, true>},
         {tiles<O::DepthOnly, true, false>, tiles<O::DepthOnly, true, true>}},
        {{tiles<O::PrimitiveId, false, false>, tiles<O::PrimitiveId, false, true>},
         {tiles<O::PrimitiveId, true, false>, tiles<O::PrimitiveId, true, true>}},
        {{tiles<O::ConstantColor, false, false>, tiles<O::ConstantColor, false, true>},
         {tiles<O::ConstantColor, true, false>, tiles<O::ConstantColor, true, true>}},
        {{tiles<O::VaryingColor, false, false>, tiles<O::VaryingColor, false, true>},
         {tiles<O::VaryingColor, true, false>, tiles<O::VaryingColor, true, true>}},
        {{tiles<O::FragmentList, false, false>, tiles<O::FragmentList, false, true>},
         {tiles<O::FragmentList, true, false>, tiles<O::FragmentList, true, true>}},
    }};
    return table;
}
