// Triangle setup (setup_kernel.h), a vector of triangles at a time, one per double lane:
// culling, pixel bounds, the integer edge functions with the top-left rule, and the depth and
// varying planes. Included by the per-ISA units inside their own namespace with
// `namespace simd = <that ISA's types>`, as tile_raster.inl is.
//
// Exact integers in double. Window coordinates are snapped integers below 2^22 in magnitude
// (fixed_point.h), so every edge coefficient (< 2^23), edge constant (< 2^46) and
// determinant (< 2^47) below is an integer that double holds exactly: each product, sum and
// floor(K / 256) is the integer result, whatever the lane width.
//
// Edge functions. For the edge from a to b, E(p) = (b.x - a.x)(p.y - a.y) - (b.y - a.y)(p.x - a.x)
// in sub-pixel units (window y grows downwards). It is positive inside a triangle whose
// determinant is positive; for the other orientation all three are negated, so the interior
// is always E >= 0, written A*x + B*y + C. Two triangles sharing an edge get exactly
// opposite (A, B, C), because the arithmetic is exact.
//
// Top-left rule (as Direct3D defines it in window coordinates with y down): a pixel centre
// exactly on an edge belongs to the triangle only if that edge is a left edge (the interior
// lies to its right, A > 0) or a top edge (horizontal with the interior below, A == 0 and
// B > 0). Of two triangles sharing an edge exactly one sees it as top-left, so a closed mesh
// covers every pixel centre exactly once. Non-top-left edges get a bias of -1.
//
// Reduction to pixel units. At pixel centre (i, j) = (256 i + 128, 256 j + 128) sub-pixels:
//   E = 256 (A i + B j) + K,  K = 128 A + 128 B + C - bias,
// and since A i + B j is an integer, E >= 0  <=>  A i + B j + floor(K / 256) >= 0.
// The tile kernels evaluate e = A i + B j + c with c = floor(K / 256): exact, in pixel steps.
//
// Conservative mode (outer): the triangle touches the pixel square iff, for every edge, the
// square's corner furthest inside has E >= 0, and the bounding boxes overlap (the separating
// axis theorem in 2-D: the axes are the three edge normals and x and y). The furthest corner
// adds 128 (|A| + |B|); 129 instead of 128 also covers the half sub-pixel that snapping may
// have moved each vertex, so no pixel the unsnapped triangle touches is missed.

using simd::F64;
using simd::Mask64;

struct SetupCorner {
    F64 x, y, z, inverseW;
    F64 varyings[kMaxVaryings];
};

struct SetupLanes {
    SetupCorner corner[3];
    F64 maxDepth;
};

inline SetupLanes loadLanes(const SetupBatch& batch, int first, int varyingCount) {
    SetupLanes lanes;
    for (int k = 0; k < 3; ++k) {
        SetupCorner& c = lanes.corner[k];
        c.x = simd::load(&batch.x[k][first]), c.y = simd::load(&batch.y[k][first]);
        c.z = simd::load(&batch.z[k][first]), c.inverseW = simd::load(&batch.inverseW[k][first]);
        for (int v = 0; v < varyingCount; ++v) c.varyings[v] = simd::load(&batch.varyings[v][k][first]);
    }
    lanes.maxDepth = simd::load(&batch.maxDepth[first]);
    return lanes;
}

// a comes before b in (y, x) order.
inline Mask64 precedes(const SetupCorner& a, const SetupCorner& b) {
    return simd::cmpLt(a.y, b.y) | (simd::cmpEq(a.y, b.y) & simd::cmpLt(a.x, b.x));
}

// out = m ? a : b lane by lane, and below a copy, for what setup reads of a corner: the
// coordinates and the draw's varyings. (Whole SetupCorner copies, kMaxVaryings varyings
// each, 768 bytes on AVX-512, were a third of setup's time.) `out` may be `b`.
inline void selectCorner(Mask64 m, const SetupCorner& a, const SetupCorner& b, int varyingCount, SetupCorner& out) {
    out.x = simd::select(m, a.x, b.x), out.y = simd::select(m, a.y, b.y);
    out.z = simd::select(m, a.z, b.z), out.inverseW = simd::select(m, a.inverseW, b.inverseW);
    for (int v = 0; v < varyingCount; ++v) out.varyings[v] = simd::select(m, a.varyings[v], b.varyings[v]);
}

inline void copyCorner(SetupCorner& to, const SetupCorner& from, int varyingCount) {
    to.x = from.x, to.y = from.y, to.z = from.z, to.inverseW = from.inverseW;
    for (int v = 0; v < varyingCount; ++v) to.varyings[v] = from.varyings[v];
}

// Rotates each lane's corners (winding kept) so the one with the smallest (y, x) comes
// first: the planes are then computed from the same base vertex however the triangle was
// submitted (llvmpipe warns that the same primitive rotated otherwise gives different z).
inline void canonicalRotation(SetupCorner (&c)[3], int varyingCount) {
    const Mask64 second = precedes(c[1], c[0]);
    SetupCorner lower;   // the first of corners 0 and 1; precedes reads its x and y
    selectCorner(second, c[1], c[0], 0, lower);
    const Mask64 third = precedes(c[2], lower);
    SetupCorner r[3];
    for (int k = 0; k < 3; ++k) {
        selectCorner(second, c[(k + 1) % 3], c[k], varyingCount, r[k]);
        selectCorner(third, c[(k + 2) % 3], r[k], varyingCount, r[k]);
    }
    for (int k = 0; k < 3; ++k) copyCorner(c[k], r[k], varyingCount);
}

inline F64 ceil(F64 a) { return simd::splat64(0.0) - simd::floor(simd::splat64(0.0) - a); }

// The pixels a triangle may cover, and its planes' reference pixel. Bounds are computed in
// the viewport's pixels, then moved to the framebuffer's (the window's, pipeline_state.h)
// and clamped to it; the reference pixel is the bounds' first pixel clamped to the
// viewport instead, so it is the same in every window of one viewport (and, without a
// window, the bounds' first pixel as before).
struct PixelBounds {
    F64 minX, minY, maxX, maxY;   // half-open, clamped to the framebuffer, framebuffer pixels
    F64 refX, refY;               // viewport pixels
};

inline PixelBounds pixelBounds(const SetupCorner (&c)[3], const SetupConstants& constants) {
    F64 lo[2] = {simd::min(simd::min(c[0].x, c[1].x), c[2].x), simd::min(simd::min(c[0].y, c[1].y), c[2].y)};
    F64 hi[2] = {simd::max(simd::max(c[0].x, c[1].x), c[2].x), simd::max(simd::max(c[0].y, c[1].y), c[2].y)};
    const F64 one = simd::splat64(1.0), perSubpixel = simd::splat64(1.0 / kSubpixelOne);
    F64 first[2], end[2];
    for (int axis = 0; axis < 2; ++axis) {
        if (constants.conservative) {
            // Pixel i touches [lo - 1, hi + 1] iff 256 i <= hi + 1 and 256 (i + 1) >= lo - 1.
            first[axis] = ceil((lo[axis] - one) * perSubpixel) - one;
            end[axis] = simd::floor((hi[axis] + one) * perSubpixel) + one;
        } else {
            // Pixel centres 256 i + 128 inside [lo, hi].
            const F64 half = simd::splat64(kSubpixelHalf);
            first[axis] = ceil((lo[axis] - half) * perSubpixel);
            end[axis] = simd::floor((hi[axis] - half) * perSubpixel) + one;
        }
    }
    const F64 zero = simd::splat64(0.0);
    const F64 windowX = simd::splat64(constants.windowX), windowY = simd::splat64(constants.windowY);
    return {simd::max(first[0] - windowX, zero),
            simd::max(first[1] - windowY, zero),
            simd::min(end[0] - windowX, simd::splat64(constants.width)),
            simd::min(end[1] - windowY, simd::splat64(constants.height)),
            simd::max(first[0], zero),
            simd::max(first[1], zero)};
}

struct Edges {
    F64 a[3], b[3], c[3];   // c = floor(K / 256), in pixel units
};

// The edge functions in framebuffer pixels: e(i, j) evaluated at viewport pixel (i + windowX,
// j + windowY), so c gains A windowX + B windowY (exact: integers below 2^37).
inline Edges setupEdges(const SetupCorner (&v)[3], F64 sign, const SetupConstants& constants) {
    const bool conservative = constants.conservative;
    const F64 windowX = simd::splat64(constants.windowX), windowY = simd::splat64(constants.windowY);
    const F64 zero = simd::splat64(0.0), half = simd::splat64(kSubpixelHalf), perSubpixel = simd::splat64(1.0 / kSubpixelOne);
    Edges e;
    for (int k = 0; k < 3; ++k) {
        const SetupCorner &a = v[k], &b = v[(k + 1) % 3];
        const F64 A = zero - sign * (b.y - a.y), B = sign * (b.x - a.x);
        const F64 C = zero - (A * a.x + B * a.y);
        F64 K = half * (A + B) + C;
        if (conservative) {
            K = K + simd::splat64(kSubpixelHalf + 1) * (simd::abs(A) + simd::abs(B));
        } else {
            const Mask64 topLeft = simd::cmpLt(zero, A) | (simd::cmpEq(A, zero) & simd::cmpLt(zero, B));
            K = K - simd::select(topLeft, zero, simd::splat64(1.0));
        }
        e.a[k] = A, e.b[k] = B, e.c[k] = simd::floor(K * perSubpixel) + A * windowX + B * windowY;
    }
    return e;
}

// What every attribute's plane over a triangle shares: the base vertex and the other two
// relative to it, in pixels, the inverse of their determinant, and the reference pixel
// centre relative to the base vertex.
struct PlaneBasis {
    F64 x1, y1, x2, y2, inverseDet, refX, refY;
};

inline PlaneBasis planeBasis(const SetupCorner (&c)[3], const PixelBounds& bounds) {
    const F64 perSubpixel = simd::splat64(1.0 / kSubpixelOne), half = simd::splat64(0.5);
    const F64 x0 = c[0].x * perSubpixel, y0 = c[0].y * perSubpixel;
    PlaneBasis b;
    b.x1 = c[1].x * perSubpixel - x0, b.y1 = c[1].y * perSubpixel - y0;
    b.x2 = c[2].x * perSubpixel - x0, b.y2 = c[2].y * perSubpixel - y0;
    b.inverseDet = simd::splat64(1.0) / (b.x1 * b.y2 - b.x2 * b.y1);
    b.refX = bounds.refX + half - x0, b.refY = bounds.refY + half - y0;
    return b;
}

// The affine function of window (x, y) taking values q[k] at the three corners: its value
// at the centre of the reference pixel and its slopes, in double.
struct PlaneLanes {
    F64 atRef, perX, perY;
};

inline PlaneLanes planeThrough(const PlaneBasis& b, F64 q0, F64 q1, F64 q2) {
    const F64 perX = ((q1 - q0) * b.y2 - (q2 - q0) * b.y1) * b.inverseDet;
    const F64 perY = ((q2 - q0) * b.x1 - (q1 - q0) * b.x2) * b.inverseDet;
    return {q0 + perX * b.refX + perY * b.refY, perX, perY};
}

// OpenGL 4.6 section 14.6.5: factor * max slope + units * r, where for a float depth buffer
// r = 2^(e - 23) and e is the exponent of the primitive's largest depth (2^e <= maxDepth <
// 2^(e + 1)). The slope is the float plane's. The binade is taken at 2^64 times the depth so
// that a subnormal depth is normal there; a depth of 0 takes r = 2^-24 (frexp's exponent 0).
inline F64 polygonOffset(const PolygonOffset& offset, F64 maxDepth, const PlaneLanes& depth) {
    if (offset.factor == 0.0f && offset.units == 0.0f) return simd::splat64(0.0);
    const F64 maxSlope = simd::max(simd::abs(simd::roundToFloat(depth.perX)), simd::abs(simd::roundToFloat(depth.perY)));
    const F64 binade = simd::binade(maxDepth * simd::splat64(0x1p64)) * simd::splat64(0x1p-87);
    const F64 r = simd::select(simd::cmpEq(maxDepth, simd::splat64(0.0)), simd::splat64(0x1p-24), binade);
    return simd::splat64(offset.factor) * maxSlope + simd::splat64(offset.units) * r;
}

struct PlaneStore {
    alignas(64) double atRef[simd::kWidth64], perX[simd::kWidth64], perY[simd::kWidth64];
};

inline void storePlane(const PlaneLanes& p, F64 offset, PlaneStore& out) {
    simd::store(out.atRef, p.atRef + offset), simd::store(out.perX, p.perX), simd::store(out.perY, p.perY);
}

inline Plane lanePlane(const PlaneStore& p, int lane) {
    return {float(p.atRef[lane]), float(p.perX[lane]), float(p.perY[lane])};
}

// The lanes' results as arrays, read back one accepted lane at a time into TriangleSetup.
struct SetupStore {
    alignas(64) double edgeA[3][simd::kWidth64], edgeB[3][simd::kWidth64], edgeC[3][simd::kWidth64];
    alignas(64) double minX[simd::kWidth64], minY[simd::kWidth64], maxX[simd::kWidth64], maxY[simd::kWidth64];
    alignas(64) double refX[simd::kWidth64], refY[simd::kWidth64];   // framebuffer pixels
    PlaneStore planes[1 + kMaxVaryings];   // depth, then the varying planes
};

inline void appendTriangle(const SetupStore& s, int lane, bool frontFacing, uint32_t primitiveId, int planeCount,
                           SetupOutput& out) {
    TriangleSetup& t = out.triangles[out.count];
    for (int k = 0; k < 3; ++k) {
        t.edgeA[k] = int32_t(s.edgeA[k][lane]), t.edgeB[k] = int32_t(s.edgeB[k][lane]), t.edgeC[k] = int64_t(s.edgeC[k][lane]);
    }
    t.minX = int32_t(s.minX[lane]), t.minY = int32_t(s.minY[lane]), t.maxX = int32_t(s.maxX[lane]), t.maxY = int32_t(s.maxY[lane]);
    t.refX = int32_t(s.refX[lane]), t.refY = int32_t(s.refY[lane]);
    t.depth = lanePlane(s.planes[0], lane);
    t.varyings = nullptr;
    t.primitiveId = primitiveId;
    t.frontFacing = frontFacing;
    for (int p = 0; p < planeCount; ++p) out.planes[out.count][p] = lanePlane(s.planes[1 + p], lane);
    ++out.count;
}

// Sets up the lanes [first, first + kWidth64) of the batch (those past its count are
// ignored) and appends the accepted ones to `out`.
inline void setupLanes(const SetupBatch& batch, int first, const SetupConstants& constants, SetupOutput& out) {
    const int varyingCount = constants.planeCount > 0 ? constants.planeCount - 1 : 0;
    SetupLanes lanes = loadLanes(batch, first, varyingCount);
    SetupCorner (&v)[3] = lanes.corner;
    canonicalRotation(v, varyingCount);
    const F64 zero = simd::splat64(0.0);
    const F64 det = (v[1].x - v[0].x) * (v[2].y - v[0].y) - (v[2].x - v[0].x) * (v[1].y - v[0].y);
    // Counter-clockwise in NDC (y up) is clockwise in window space (y down): det < 0.
    const Mask64 frontFacing = simd::cmpLt(det, zero);
    Mask64 accepted = simd::firstLanes64(batch.count - first) & simd::cmpNe(det, zero);
    if (constants.cull == CullMode::Back) accepted = accepted & frontFacing;
    if (constants.cull == CullMode::Front) accepted = accepted & !frontFacing;
    const PixelBounds bounds = pixelBounds(v, constants);
    accepted = accepted & simd::cmpLt(bounds.minX, bounds.maxX) & simd::cmpLt(bounds.minY, bounds.maxY);
    const unsigned acceptedBits = simd::laneBits(accepted);
    if (acceptedBits == 0) return;

    SetupStore s;
    const Edges edges = setupEdges(v, simd::select(frontFacing, simd::splat64(-1.0), simd::splat64(1.0)), constants);
    for (int k = 0; k < 3; ++k) {
        simd::store(s.edgeA[k], edges.a[k]), simd::store(s.edgeB[k], edges.b[k]), simd::store(s.edgeC[k], edges.c[k]);
    }
    simd::store(s.minX, bounds.minX), simd::store(s.minY, bounds.minY);
    simd::store(s.maxX, bounds.maxX), simd::store(s.maxY, bounds.maxY);
    simd::store(s.refX, bounds.refX - simd::splat64(constants.windowX));
    simd::store(s.refY, bounds.refY - simd::splat64(constants.windowY));
    const PlaneBasis basis = planeBasis(v, bounds);
    const PlaneLanes depth = planeThrough(basis, v[0].z, v[1].z, v[2].z);
    storePlane(depth, polygonOffset(constants.offset, lanes.maxDepth, depth), s.planes[0]);
    if (constants.planeCount > 0) {
        // Perspective-correct interpolation: 1/w and a/w are affine in window space.
        storePlane(planeThrough(basis, v[0].inverseW, v[1].inverseW, v[2].inverseW), zero, s.planes[1]);
        for (int k = 0; k < varyingCount; ++k) {
            storePlane(planeThrough(basis, v[0].varyings[k] * v[0].inverseW, v[1].varyings[k] * v[1].inverseW,
                                    v[2].varyings[k] * v[2].inverseW), zero, s.planes[2 + k]);
        }
    }
    const unsigned frontBits = simd::laneBits(frontFacing);
    for (int lane = 0; lane < simd::kWidth64; ++lane) {
        if (acceptedBits & (1u << lane)) {
            appendTriangle(s, lane, (frontBits >> lane) & 1u, batch.primitiveId[first + lane], constants.planeCount, out);
        }
    }
}

inline void setupTriangles(const SetupBatch& batch, const SetupConstants& constants, SetupOutput& out) {
    out.count = 0;
    for (int first = 0; first < batch.count; first += simd::kWidth64) setupLanes(batch, first, constants, out);
}
