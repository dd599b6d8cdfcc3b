// portable::exp's operations (portable_math.h) on SIMD lanes, the constants shared through
// portable_constants.h, written against the types of
// raster/simd/ (a namespace alias `simd` chosen by the including file).

inline simd::F64 expLanes(simd::F64 x) {
    using simd::F64;
    using simd::splat64;
    // x = k ln 2 + r, |r| <= ln 2 / 2, with ln 2 split so that k ln2High is exact.
    const F64 k = simd::floor(x * splat64(detail::kInvLn2) + splat64(0.5));
    const F64 r = (x - k * splat64(detail::kLn2High)) - k * splat64(detail::kLn2Low);
    F64 sum = splat64(detail::kInverseFactorial.value[16]);
    for (int n = 15; n >= 0; --n) sum = sum * r + splat64(detail::kInverseFactorial.value[n]);
    // 2^k in two factors 2^h and 2^(k - h), h = int(k) / 2 (C++ truncates towards zero).
    const F64 zero = splat64(0.0), half = splat64(0.5);
    const F64 h = simd::select(simd::cmpLt(k, zero), zero - simd::floor((zero - k) * half), simd::floor(k * half));
    const F64 scaled = (sum * simd::powerOfTwo(h)) * simd::powerOfTwo(k - h);
    // The special cases, in portable::exp's order: NaN, then overflow, then underflow.
    F64 e = simd::select(simd::cmpLt(x, splat64(detail::kExpUnderflow)), zero, scaled);
    e = simd::select(simd::cmpLt(splat64(detail::kExpOverflow), x), splat64(__builtin_inf()), e);
    return simd::select(simd::cmpNe(x, x), x, e);
}

inline void expRunLanes(const double* x, double* out, size_t count) {
    for (size_t k = 0; k < count; k += simd::kWidth64) simd::store(out + k, expLanes(simd::load(x + k)));
}

// The table the per-ISA unit hands out (cmake/isa_kernels.cmake).
inline ExpKernel kernels() { return {simd::kWidth64, expRunLanes}; }
