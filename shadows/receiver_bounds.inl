// The receivers' bounds in a light's view (receiver_bounds.h), a vector of points at a time.
// Written against the SIMD types of raster/simd/ (a namespace alias `simd` chosen by the
// including file).

// glm's dmat4 * dvec4(P, 1), row r: (m0 x + m1 y) + (m2 z + m3), its additions in its order.
inline simd::F64 transformed(const double* m, int r, simd::F64 x, simd::F64 y, simd::F64 z) {
    return (simd::splat64(m[r]) * x + simd::splat64(m[4 + r]) * y) + (simd::splat64(m[8 + r]) * z + simd::splat64(m[12 + r]));
}

template <int kSpace>
void boundsOf(const BoundsRun& run, BoundsResult& result) {
    const simd::F64 inf = simd::splat64(__builtin_inf()), minusInf = simd::splat64(-__builtin_inf());
    const simd::F64 zero = simd::splat64(0.0), negativeZero = simd::splat64(-0.0);
    simd::F64 lo[3] = {inf, inf, inf}, hi[3] = {minusInf, minusInf, minusInf};
    simd::Mask64 behind = !simd::firstLanes64(simd::kWidth64);   // no lane
    for (size_t k = 0; k < run.count; k += simd::kWidth64) {
        simd::F64 x, y, z;
        simd::loadTriplesWidened(run.position + 3 * k, x, y, z);
        simd::F64 value[3] = {x, y, z};
        if (kSpace != kWorldBox) {
            const simd::F64 qx = transformed(run.matrix, 0, x, y, z), qy = transformed(run.matrix, 1, x, y, z);
            const simd::F64 depth = negativeZero - transformed(run.matrix, 2, x, y, z);   // exactly -q.z
            value[0] = qx, value[1] = qy, value[2] = depth;
            if (kSpace == kPerspectiveView) value[0] = qx / depth, value[1] = qy / depth;
        }
        const simd::Mask64 served = simd::nonZero64(run.served + k);
        if (kSpace == kPerspectiveView) behind = behind | (served & !simd::cmpLt(zero, value[2]));
        // The running bound second: min and max return it where the value is NaN or equal,
        // as std::min(bound, value) and std::max(bound, value) do.
        for (int c = 0; c < 3; ++c) {
            lo[c] = simd::min(simd::select(served, value[c], inf), lo[c]);
            hi[c] = simd::max(simd::select(served, value[c], minusInf), hi[c]);
        }
    }
    // Plain comparisons, not std::min: this file is built per instruction set and may
    // define no function the rest of the program could link to.
    for (int c = 0; c < 3; ++c) {
        const double low = simd::reduceMin(lo[c]), high = simd::reduceMax(hi[c]);
        result.lo[c] = low < result.lo[c] ? low : result.lo[c];
        result.hi[c] = result.hi[c] < high ? high : result.hi[c];
    }
    result.behindApex = result.behindApex || simd::laneBits(behind) != 0;
}

inline const BoundsKernels& kernels() {
    static const BoundsKernels k{simd::kWidth64, {boundsOf<kWorldBox>, boundsOf<kOrthographicView>, boundsOf<kPerspectiveView>}};
    return k;
}
