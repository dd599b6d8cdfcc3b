// Eight-lane types on AVX2. Same interface and same lane results as simd_scalar.h.
// Masks are vectors with all bits of a true lane set (the form compares produce).
#pragma once

#include <immintrin.h>

#include <cstdint>

namespace shadowlab::simd_avx2 {

inline constexpr int kWidth = 8;

struct F32 { __m256 v; };
struct I32 { __m256i v; };
struct Mask { __m256i v; };

inline F32 splat(float x) { return {_mm256_set1_ps(x)}; }
inline I32 splat(int32_t x) { return {_mm256_set1_epi32(x)}; }
inline I32 laneIndex() { return {_mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7)}; }

inline F32 load(const float* p) { return {_mm256_loadu_ps(p)}; }
inline I32 load(const uint32_t* p) { return {_mm256_loadu_si256(reinterpret_cast<const __m256i*>(p))}; }
inline I32 loadU8(const uint8_t* p) {
    return {_mm256_cvtepu8_epi32(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(p)))};
}
// Lane k of x, y, z from p[3k], p[3k + 1], p[3k + 2]: element e = 3k + c of the 24 lies in
// vector e / 8 at lane e % 8; each vector is permuted there and the three are blended.
inline void loadTriples(const float* p, F32& x, F32& y, F32& z) {
    const __m256 a = _mm256_loadu_ps(p), b = _mm256_loadu_ps(p + 8), c = _mm256_loadu_ps(p + 16);
    // x: elements 0 3 6 | 9 12 15 | 18 21; y: 1 4 7 | 10 13 | 16 19 22; z: 2 5 | 8 11 14 | 17 20 23.
    const __m256i lanesX = _mm256_setr_epi32(0, 3, 6, 1, 4, 7, 2, 5);
    const __m256i lanesY = _mm256_setr_epi32(1, 4, 7, 2, 5, 0, 3, 6);
    const __m256i lanesZ = _mm256_setr_epi32(2, 5, 0, 3, 6, 1, 4, 7);
    x = {_mm256_blend_ps(_mm256_blend_ps(_mm256_permutevar8x32_ps(a, lanesX), _mm256_permutevar8x32_ps(b, lanesX), 0x38),
                         _mm256_permutevar8x32_ps(c, lanesX), 0xc0)};
    y = {_mm256_blend_ps(_mm256_blend_ps(_mm256_permutevar8x32_ps(a, lanesY), _mm256_permutevar8x32_ps(b, lanesY), 0x18),
                         _mm256_permutevar8x32_ps(c, lanesY), 0xe0)};
    z = {_mm256_blend_ps(_mm256_blend_ps(_mm256_permutevar8x32_ps(a, lanesZ), _mm256_permutevar8x32_ps(b, lanesZ), 0x1c),
                         _mm256_permutevar8x32_ps(c, lanesZ), 0xe0)};
}
inline void store(float* p, F32 a) { _mm256_storeu_ps(p, a.v); }
inline void store(uint32_t* p, I32 a) { _mm256_storeu_si256(reinterpret_cast<__m256i*>(p), a.v); }
inline void storeU8(uint8_t* p, I32 a) {
    // Lanes hold 0..255; the unsigned saturating packs then narrow without changing them.
    const __m128i words = _mm_packus_epi32(_mm256_castsi256_si128(a.v), _mm256_extracti128_si256(a.v, 1));
    _mm_storel_epi64(reinterpret_cast<__m128i*>(p), _mm_packus_epi16(words, words));
}

inline F32 operator+(F32 a, F32 b) { return {_mm256_add_ps(a.v, b.v)}; }
inline F32 operator-(F32 a, F32 b) { return {_mm256_sub_ps(a.v, b.v)}; }
inline F32 operator*(F32 a, F32 b) { return {_mm256_mul_ps(a.v, b.v)}; }
inline F32 operator/(F32 a, F32 b) { return {_mm256_div_ps(a.v, b.v)}; }
inline F32 min(F32 a, F32 b) { return {_mm256_min_ps(a.v, b.v)}; }
inline F32 max(F32 a, F32 b) { return {_mm256_max_ps(a.v, b.v)}; }
inline F32 sqrt(F32 a) { return {_mm256_sqrt_ps(a.v)}; }
inline F32 floor(F32 a) { return {_mm256_round_ps(a.v, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC)}; }
inline F32 toFloat(I32 a) { return {_mm256_cvtepi32_ps(a.v)}; }
inline I32 truncateToInt(F32 a) { return {_mm256_cvttps_epi32(a.v)}; }
inline F32 gather(const float* p, I32 index) { return {_mm256_i32gather_ps(p, index.v, 4)}; }

inline I32 operator+(I32 a, I32 b) { return {_mm256_add_epi32(a.v, b.v)}; }
inline I32 operator-(I32 a, I32 b) { return {_mm256_sub_epi32(a.v, b.v)}; }
inline I32 operator*(I32 a, I32 b) { return {_mm256_mullo_epi32(a.v, b.v)}; }
inline I32 operator&(I32 a, I32 b) { return {_mm256_and_si256(a.v, b.v)}; }
inline I32 operator|(I32 a, I32 b) { return {_mm256_or_si256(a.v, b.v)}; }
inline I32 operator^(I32 a, I32 b) { return {_mm256_xor_si256(a.v, b.v)}; }
inline I32 min(I32 a, I32 b) { return {_mm256_min_epi32(a.v, b.v)}; }
inline I32 max(I32 a, I32 b) { return {_mm256_max_epi32(a.v, b.v)}; }
template <int kBits> inline I32 shiftRight(I32 a) { return {_mm256_srai_epi32(a.v, kBits)}; }
template <int kBits> inline I32 shiftLeft(I32 a) { return {_mm256_slli_epi32(a.v, kBits)}; }

// Ordered compares are false on NaN and "not equal" is true on NaN, as in C++.
inline Mask cmpLt(F32 a, F32 b) { return {_mm256_castps_si256(_mm256_cmp_ps(a.v, b.v, _CMP_LT_OQ))}; }
inline Mask cmpLe(F32 a, F32 b) { return {_mm256_castps_si256(_mm256_cmp_ps(a.v, b.v, _CMP_LE_OQ))}; }
inline Mask cmpEq(F32 a, F32 b) { return {_mm256_castps_si256(_mm256_cmp_ps(a.v, b.v, _CMP_EQ_OQ))}; }
inline Mask cmpNe(F32 a, F32 b) { return {_mm256_castps_si256(_mm256_cmp_ps(a.v, b.v, _CMP_NEQ_UQ))}; }
inline Mask cmpGt(I32 a, I32 b) { return {_mm256_cmpgt_epi32(a.v, b.v)}; }
inline Mask cmpEq(I32 a, I32 b) { return {_mm256_cmpeq_epi32(a.v, b.v)}; }

inline Mask operator&(Mask a, Mask b) { return {_mm256_and_si256(a.v, b.v)}; }
inline Mask operator|(Mask a, Mask b) { return {_mm256_or_si256(a.v, b.v)}; }
inline Mask operator!(Mask a) { return {_mm256_xor_si256(a.v, _mm256_set1_epi32(-1))}; }
inline Mask allLanes() { return {_mm256_set1_epi32(-1)}; }
inline Mask noLanes() { return {_mm256_setzero_si256()}; }
inline bool any(Mask a) { return !_mm256_testz_si256(a.v, a.v); }
inline int countLanes(Mask a) { return __builtin_popcount(unsigned(_mm256_movemask_ps(_mm256_castsi256_ps(a.v)))); }

inline F32 select(Mask m, F32 a, F32 b) { return {_mm256_blendv_ps(b.v, a.v, _mm256_castsi256_ps(m.v))}; }
inline I32 select(Mask m, I32 a, I32 b) { return {_mm256_blendv_epi8(b.v, a.v, m.v)}; }

// ---- Doubles, for exact work (setup, shadows/izb): kWidth64 lanes with their own mask ----
inline constexpr int kWidth64 = 4;
struct F64 { __m256d v; };
struct Mask64 { __m256d v; };   // all bits of a true lane set

inline F64 splat64(double x) { return {_mm256_set1_pd(x)}; }
inline F64 load(const double* p) { return {_mm256_loadu_pd(p)}; }
inline F64 loadWidened(const float* p) { return {_mm256_cvtps_pd(_mm_loadu_ps(p))}; }
inline F64 operator+(F64 a, F64 b) { return {_mm256_add_pd(a.v, b.v)}; }
inline F64 operator-(F64 a, F64 b) { return {_mm256_sub_pd(a.v, b.v)}; }
inline F64 operator*(F64 a, F64 b) { return {_mm256_mul_pd(a.v, b.v)}; }
inline F64 operator/(F64 a, F64 b) { return {_mm256_div_pd(a.v, b.v)}; }
inline F64 abs(F64 a) { return {_mm256_andnot_pd(_mm256_set1_pd(-0.0), a.v)}; }
inline F64 max(F64 a, F64 b) { return {_mm256_max_pd(a.v, b.v)}; }
inline F64 min(F64 a, F64 b) { return {_mm256_min_pd(a.v, b.v)}; }
// Lane k of x, y, z from p[3k], p[3k + 1], p[3k + 2], widened: three loads of four floats,
// a = x0 y0 z0 x1, b = y1 z1 x2 y2, c = z2 x3 y3 z3, shuffled (gathers are slow here).
inline void loadTriplesWidened(const float* p, F64& x, F64& y, F64& z) {
    const __m128 a = _mm_loadu_ps(p), b = _mm_loadu_ps(p + 4), c = _mm_loadu_ps(p + 8);
    const __m128 xs = _mm_blend_ps(_mm_shuffle_ps(a, b, _MM_SHUFFLE(2, 2, 3, 0)), _mm_shuffle_ps(c, c, _MM_SHUFFLE(1, 1, 1, 1)), 0x8);
    const __m128 ab = _mm_shuffle_ps(a, b, _MM_SHUFFLE(3, 0, 0, 1));   // y0 x0 y1 y2
    const __m128 ys = _mm_blend_ps(_mm_shuffle_ps(ab, ab, _MM_SHUFFLE(3, 3, 2, 0)), _mm_shuffle_ps(c, c, _MM_SHUFFLE(2, 2, 2, 2)), 0x8);
    const __m128 zz = _mm_shuffle_ps(a, b, _MM_SHUFFLE(1, 1, 2, 2));   // z0 z0 z1 z1
    const __m128 zs = _mm_shuffle_ps(zz, c, _MM_SHUFFLE(3, 0, 2, 0));
    x = {_mm256_cvtps_pd(xs)}, y = {_mm256_cvtps_pd(ys)}, z = {_mm256_cvtps_pd(zs)};
}
inline Mask64 nonZero64(const uint8_t* p) {
    int32_t bytes;
    __builtin_memcpy(&bytes, p, 4);
    const __m256i wide = _mm256_cvtepu8_epi64(_mm_cvtsi32_si128(bytes));
    return {_mm256_castsi256_pd(_mm256_xor_si256(_mm256_cmpeq_epi64(wide, _mm256_setzero_si256()), _mm256_set1_epi64x(-1)))};
}
inline Mask64 operator|(Mask64 a, Mask64 b) { return {_mm256_or_pd(a.v, b.v)}; }
inline double reduceMin(F64 a) {
    const __m128d m = _mm_min_pd(_mm256_castpd256_pd128(a.v), _mm256_extractf128_pd(a.v, 1));
    return _mm_cvtsd_f64(_mm_min_sd(m, _mm_unpackhi_pd(m, m)));
}
inline double reduceMax(F64 a) {
    const __m128d m = _mm_max_pd(_mm256_castpd256_pd128(a.v), _mm256_extractf128_pd(a.v, 1));
    return _mm_cvtsd_f64(_mm_max_sd(m, _mm_unpackhi_pd(m, m)));
}
inline F64 sqrt(F64 a) { return {_mm256_sqrt_pd(a.v)}; }
inline F64 roundToFloat(F64 a) { return {_mm256_cvtps_pd(_mm256_cvtpd_ps(a.v))}; }
inline F64 floor(F64 a) { return {_mm256_round_pd(a.v, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC)}; }
inline F64 powerOfTwo(F64 e) {
    const __m256d biased = _mm256_add_pd(e.v, _mm256_set1_pd(0x1.00000000003ffp52));
    return {_mm256_castsi256_pd(_mm256_slli_epi64(_mm256_castpd_si256(biased), 52))};
}
inline F64 binade(F64 a) { return {_mm256_and_pd(a.v, _mm256_castsi256_pd(_mm256_set1_epi64x(0x7ff0000000000000ll)))}; }
inline void store(double* p, F64 a) { _mm256_storeu_pd(p, a.v); }
inline void storeNarrowed(float* p, F64 a) { _mm_storeu_ps(p, _mm256_cvtpd_ps(a.v)); }
inline Mask64 cmpLt(F64 a, F64 b) { return {_mm256_cmp_pd(a.v, b.v, _CMP_LT_OQ)}; }
inline Mask64 cmpLe(F64 a, F64 b) { return {_mm256_cmp_pd(a.v, b.v, _CMP_LE_OQ)}; }
inline Mask64 cmpNe(F64 a, F64 b) { return {_mm256_cmp_pd(a.v, b.v, _CMP_NEQ_UQ)}; }
inline Mask64 cmpEq(F64 a, F64 b) { return {_mm256_cmp_pd(a.v, b.v, _CMP_EQ_OQ)}; }
inline Mask64 operator&(Mask64 a, Mask64 b) { return {_mm256_and_pd(a.v, b.v)}; }
inline Mask64 operator!(Mask64 a) { return {_mm256_xor_pd(a.v, _mm256_castsi256_pd(_mm256_set1_epi64x(-1)))}; }
// The first n lanes (n >= 0).
inline Mask64 firstLanes64(int n) {
    return {_mm256_castsi256_pd(_mm256_cmpgt_epi64(_mm256_set1_epi64x(n), _mm256_setr_epi64x(0, 1, 2, 3)))};
}
// Bit k set where lane k is true.
inline unsigned laneBits(Mask64 a) { return unsigned(_mm256_movemask_pd(a.v)); }
inline F64 select(Mask64 m, F64 a, F64 b) { return {_mm256_blendv_pd(b.v, a.v, m.v)}; }

}  // namespace shadowlab::simd_avx2
