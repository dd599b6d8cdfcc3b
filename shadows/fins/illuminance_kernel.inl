// The illuminance buffer's kernels (illuminance_kernel.h), written against the SIMD types
// of raster/simd/ (a namespace alias `simd` chosen by the including file). Each line is the
// double expression of the plain scalar code (MapReceiver, LightPlane::distance, eqs. 2 to 5),
// in the same order.

using simd::F64;
using simd::Mask64;

// glm's dmat4 * dvec4(P, 1), row r: (m0 x + m1 y) + (m2 z + m3), its additions in its order.
inline F64 transformed(const double* m, int r, F64 x, F64 y, F64 z) {
    return (simd::splat64(m[r]) * x + simd::splat64(m[4 + r]) * y) + (simd::splat64(m[8 + r]) * z + simd::splat64(m[12 + r]));
}

// std::clamp(v, lo, hi): lo below, hi above, v otherwise (NaN included).
inline F64 clamped(F64 v, F64 lo, F64 hi) { return simd::select(simd::cmpLt(v, lo), lo, simd::select(simd::cmpLt(hi, v), hi, v)); }

// std::clamp(texelIndexOf(c), 0, last) as a double: floor(c) saturated to +-2^30 (NaN to
// -2^30), then clamped to the map.
inline F64 texelOf(F64 c, F64 last) {
    const F64 limit = simd::splat64(1073741824.0), minusLimit = simd::splat64(-1073741824.0);
    const F64 saturated = simd::select(simd::cmpLt(minusLimit, c), simd::select(simd::cmpLt(c, limit), c, limit), minusLimit);
    return clamped(simd::floor(saturated), simd::splat64(0.0), last);
}

inline void placeReceivers(const PlaceConstants& c, const float* positions, uint32_t count, const PlacedColumns& out) {
    const double* m = c.texelFromWorld;
    const F64 last = simd::splat64(c.lastTexel), zero = simd::splat64(0.0), half = simd::splat64(0.5);
    for (uint32_t k = 0; k < count; k += simd::kWidth64) {
        F64 x, y, z;
        simd::loadTriplesWidened(positions + 3 * std::size_t(k), x, y, z);
        // mapReceiver: t = M (P, 1) / w, depth slope 0 (slope-scaled bias).
        const F64 w = transformed(m, 3, x, y, z);
        const F64 tx = transformed(m, 0, x, y, z) / w, ty = transformed(m, 1, x, y, z) / w;
        const F64 depth = transformed(m, 2, x, y, z) / w;
        const F64 texelX = texelOf(tx, last), texelY = texelOf(ty, last);
        // MapReceiver::depthAt(texel centre) = depth + (0, 0) . (centre - t).
        const F64 slopeTerm = zero * ((texelX + half) - tx) + zero * ((texelY + half) - ty);
        simd::store(out.x + k, texelX), simd::store(out.y + k, texelY);
        simd::store(out.depthAtCentre + k, depth + slopeTerm);
        // LightPlane::distance: (P - centre) . normal.
        const F64 lx = (x - simd::splat64(c.lightCentre[0])) * simd::splat64(c.lightNormal[0]);
        const F64 ly = (y - simd::splat64(c.lightCentre[1])) * simd::splat64(c.lightNormal[1]);
        const F64 lz = (z - simd::splat64(c.lightCentre[2])) * simd::splat64(c.lightNormal[2]);
        simd::store(out.lightDistance + k, (lx + ly) + lz);
    }
}

// A penumbra map's term at the receiver (IlluminanceBuffer's adjustment): 0 where no fin
// covers the texel or the fin lies behind the receiver, else the fin's weight refined to
// the receiver's plane (eqs. 2 to 5) after the fall-off.
inline F64 finTerm(const IlluminateConstants& c, F64 finDepth, F64 s0, F64 Lr) {
    const F64 one = simd::splat64(1.0), two = simd::splat64(2.0), zero = simd::splat64(0.0);
    const F64 e = simd::splat64(c.edgeWeight), L0 = simd::splat64(c.referenceDistance);
    const F64 Lb = simd::splat64(c.depthRow32) / ((two * finDepth - one) + simd::splat64(c.depthRow22));
    const F64 widthRatio = ((L0 - Lb) / L0) * (Lr / (Lr - Lb));   // B_0 / B_r
    F64 s = clamped(e + widthRatio * (s0 - e), zero, e);
    if (c.bernstein) s = s * s * (simd::splat64(3.0) - two * s);
    return simd::select(simd::cmpLt(finDepth, one) & simd::cmpLt(Lb, Lr), s, zero);
}

inline void illuminate(const IlluminateConstants& c, const PlacedColumns& placed, const TexelColumns& t, uint32_t count,
                       float* values) {
    const F64 one = simd::splat64(1.0), zero = simd::splat64(0.0);
    for (uint32_t k = 0; k < count; k += simd::kWidth64) {
        const F64 stored = simd::load(t.hardDepth + k), Lr = simd::load(placed.lightDistance + k);
        // MapReceiver::litBy: an empty texel (1) or a receiver not behind what it stores.
        const Mask64 lit = simd::cmpLe(one, stored) | simd::cmpLe(simd::load(placed.depthAtCentre + k), stored);
        F64 local = simd::select(lit, one, zero);
        if (t.innerDepth) local = local + finTerm(c, simd::load(t.innerDepth + k), simd::load(t.innerWeight + k), Lr);
        local = local - finTerm(c, simd::load(t.outerDepth + k), simd::load(t.outerWeight + k), Lr);
        // I = std::min(I, float(clamp(local, 0, 1))).
        const F64 candidate = simd::roundToFloat(clamped(local, zero, one)), previous = simd::loadWidened(values + k);
        simd::storeNarrowed(values + k, simd::select(simd::cmpLt(candidate, previous), candidate, previous));
    }
}

// The table the per-ISA unit hands out (cmake/isa_kernels.cmake).
inline IlluminanceKernels kernels() { return {simd::kWidth64, placeReceivers, illuminate}; }
