// Irregular z-buffer, stage 6: the exact test of receivers against one occluder, written
// once against the SIMD types of raster/simd/ (a namespace alias `simd` chosen by the
// including file), lane by lane in double precision.
//
// Aila and Laine (2004) test whether the sample lies inside the triangle's projection from
// the light and behind its plane; for a segment from the receiver O to the light that is a
// segment-triangle intersection, evaluated with signed volumes (the side tests of Pluecker
// coordinates). With A, B, C the vertices relative to O and d the direction to the light,
// the line O + t d passes through the triangle iff the three volumes
//     e_AB = det(A, B, d), e_BC = det(B, C, d), e_CA = det(C, A, d)
// share a sign; their sum is det(B - A, C - A, d) = n . d (n the unnormalised plane normal),
// and the plane is met at t = det(A, B, C) / (n . d).
//
// Why this is robust where it matters:
//  - Watertight: an edge shared by two triangles gives bit-identical volumes of opposite
//    sign in both, since swapping the operands of a cross product negates each rounded
//    component exactly; a zero volume counts as inside (closed edges), so a segment through
//    a shared edge is blocked by at least one of the two triangles and never slips between.
//  - Precise: vertices, origins and the light are floats or near-float doubles, so A, B, C
//    are exact or nearly so, and each volume carries a relative error of a few 2^-53, far
//    below the float rounding the reference's Embree rays carry (about 2^-24). The two
//    disagree only where the segment passes within ~1e-7 of its length from an occluder's
//    edge: ties, which the exact techniques' tests allow right at a shadow boundary.

using simd::F64;
using simd::Mask64;

struct Vec3Lanes {
    F64 x, y, z;
};

inline Vec3Lanes operator-(const Vec3Lanes& a, const Vec3Lanes& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }

// det(a, b, c) = (a x b) . c, the products and sums in glm's order (cross, then dot summed
// x + y + z), so the scalar build is the plain double expression.
inline F64 det(const Vec3Lanes& a, const Vec3Lanes& b, const Vec3Lanes& c) {
    const F64 cx = a.y * b.z - b.y * a.z, cy = a.z * b.x - b.z * a.x, cz = a.x * b.y - b.x * a.y;
    return cx * c.x + cy * c.y + cz * c.z;
}

// Where the segments meet the triangle's plane: the lanes whose segment origin + t *
// towardsLight, t in [0, tFar], meets the triangle, and the signed volumes whose ratios
// to nd are the meeting point's barycentric coordinates (u, v) = (eCA, eAB) / nd, the
// weights of B and C (the reference's Embree hit's u and v).
struct Crossing {
    Mask64 hit;
    F64 eCA, eAB, nd;
};

inline Crossing segmentsCrossing(const Vec3Lanes& origin, const Vec3Lanes& towardsLight, F64 tFar,
                                 const Vec3Lanes (&triangle)[3]) {
    const Vec3Lanes A = triangle[0] - origin, B = triangle[1] - origin, C = triangle[2] - origin;
    const F64 eAB = det(A, B, towardsLight), eBC = det(B, C, towardsLight), eCA = det(C, A, towardsLight);
    const F64 nd = eAB + eBC + eCA;
    const F64 zero = simd::splat64(0.0);
    // A triangle seen edge-on from the light (nd = 0) covers no area of its projection.
    const Mask64 faced = simd::cmpNe(nd, zero);
    const F64 s = simd::select(simd::cmpLt(zero, nd), simd::splat64(1.0), simd::splat64(-1.0));
    const auto sameSide = [&](F64 e) { return !simd::cmpLt(s * e, zero); };   // zero counts: closed edges
    const Mask64 inside = sameSide(eAB) & sameSide(eBC) & sameSide(eCA);
    // 0 <= t <= tFar with t = det(A, B, C) / nd, compared without dividing.
    const F64 t = s * det(A, B, C), range = s * nd;
    return {faced & inside & simd::cmpLe(zero, t) & simd::cmpLe(t, tFar * range), eCA, eAB, nd};
}

// Lanes whose segment meets the triangle: a solid occluder's test, its volumes unused.
inline Mask64 segmentsBlocked(const Vec3Lanes& origin, const Vec3Lanes& towardsLight, F64 tFar,
                              const Vec3Lanes (&triangle)[3]) {
    return segmentsCrossing(origin, towardsLight, tFar, triangle).hit;
}

inline Vec3Lanes splat(const double* xyz) { return {simd::splat64(xyz[0]), simd::splat64(xyz[1]), simd::splat64(xyz[2])}; }

// Receiver k's segment in lanes k, k + 1, ...: its origin, and the direction to the light.
inline Vec3Lanes originsAt(const ReceiverColumns& receivers, uint32_t k) {
    return {simd::loadWidened(receivers.x + k), simd::loadWidened(receivers.y + k), simd::loadWidened(receivers.z + k)};
}
inline Vec3Lanes towardsLightFrom(const Vec3Lanes& origin, const Vec3Lanes& light, F64 w) {
    return {light.x - w * origin.x, light.y - w * origin.y, light.z - w * origin.z};
}

// The OcclusionKernel (kernels.h): the run in vectors of kWidth64 receivers, the
// last one cut to the run by a lane mask (the arrays are padded, so its loads stay inside).
inline void blockRun(const OccluderTriangle& occluder, const ReceiverColumns& receivers, uint32_t begin, uint32_t end,
                     uint8_t* blocked) {
    const Vec3Lanes triangle[3] = {splat(occluder.vertex), splat(occluder.vertex + 3), splat(occluder.vertex + 6)};
    const Vec3Lanes light = splat(occluder.light);
    const F64 w = simd::splat64(occluder.light[3]);
    for (uint32_t k = begin; k < end; k += simd::kWidth64) {
        const Vec3Lanes origin = originsAt(receivers, k);
        const Mask64 hit = segmentsBlocked(origin, towardsLightFrom(origin, light, w), simd::load(receivers.tFar + k),
                                           triangle) &
                           simd::firstLanes64(int(end - k));
        // Hits are rare (an occluder's footprint is mostly lit receivers): one store each.
        for (unsigned bits = simd::laneBits(hit); bits != 0; bits &= bits - 1) blocked[k + __builtin_ctz(bits)] = 1;
    }
}

// The CrossingKernel (kernels.h): as blockRun, but each hit is listed with where it meets
// the triangle, for a cut-out's alpha test; the barycentric coordinates are divided and
// rounded to float per hit, in scalar code, so every level gives the same bits.
inline uint32_t crossRun(const OccluderTriangle& occluder, const ReceiverColumns& receivers, uint32_t begin,
                         uint32_t end, SegmentHit* hits) {
    const Vec3Lanes triangle[3] = {splat(occluder.vertex), splat(occluder.vertex + 3), splat(occluder.vertex + 6)};
    const Vec3Lanes light = splat(occluder.light);
    const F64 w = simd::splat64(occluder.light[3]);
    uint32_t count = 0;
    for (uint32_t k = begin; k < end; k += simd::kWidth64) {
        const Vec3Lanes origin = originsAt(receivers, k);
        const Crossing c = segmentsCrossing(origin, towardsLightFrom(origin, light, w), simd::load(receivers.tFar + k),
                                            triangle);
        unsigned bits = simd::laneBits(c.hit & simd::firstLanes64(int(end - k)));
        if (bits == 0) continue;
        alignas(64) double eCA[simd::kWidth64], eAB[simd::kWidth64], nd[simd::kWidth64];
        simd::store(eCA, c.eCA), simd::store(eAB, c.eAB), simd::store(nd, c.nd);
        for (; bits != 0; bits &= bits - 1) {
            const int lane = __builtin_ctz(bits);
            hits[count++] = {k + uint32_t(lane), float(eCA[lane] / nd[lane]), float(eAB[lane] / nd[lane])};
        }
    }
    return count;
}
