// Sixteen-lane types on AVX-512 (F and BW). Same interface and same lane results as
// simd_scalar.h. Masks are the k-registers that AVX-512 compares produce.
#pragma once

#include <immintrin.h>

#include <cstdint>

namespace shadowlab::simd_avx512 {

inline constexpr int kWidth = 16;

struct F32 { __m512 v; };
struct I32 { __m512i v; };
struct Mask { __mmask16 v; };

inline F32 splat(float x) { return {_mm512_set1_ps(x)}; }
inline I32 splat(int32_t x) { return {_mm512_set1_epi32(x)}; }
inline I32 laneIndex() { return {_mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15)}; }

inline F32 load(const float* p) { return {_mm512_loadu_ps(p)}; }
inline I32 load(const uint32_t* p) { return {_mm512_loadu_si512(p)}; }
inline I32 loadU8(const uint8_t* p) {
    return {_mm512_cvtepu8_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(p)))};
}
// Lane k of x, y, z from p[3k], p[3k + 1], p[3k + 2]: element e = 3k + c of the 48 comes
// from the first two vectors while e < 32 (one two-source permute), and from the third
// after (a second permute that keeps the lanes already placed).
inline F32 tripleComponent(__m512 a, __m512 b, __m512 c, int component) {
    alignas(64) int32_t first[16], second[16];
    for (int k = 0; k < 16; ++k) {
        const int e = 3 * k + component;
        first[k] = e < 32 ? e : 0;
        second[k] = e < 32 ? k : 16 + e - 32;
    }
    const __m512 ab = _mm512_permutex2var_ps(a, _mm512_load_si512(first), b);
    return {_mm512_permutex2var_ps(ab, _mm512_load_si512(second), c)};
}
inline void loadTriples(const float* p, F32& x, F32& y, F32& z) {
    const __m512 a = _mm512_loadu_ps(p), b = _mm512_loadu_ps(p + 16), c = _mm512_loadu_ps(p + 32);
    x = tripleComponent(a, b, c, 0), y = tripleComponent(a, b, c, 1), z = tripleComponent(a, b, c, 2);
}
inline void store(float* p, F32 a) { _mm512_storeu_ps(p, a.v); }
inline void store(uint32_t* p, I32 a) { _mm512_storeu_si512(p, a.v); }
inline void storeU8(uint8_t* p, I32 a) {
    // Lanes hold 0..255, so truncating each to a byte keeps it.
    _mm_storeu_si128(reinterpret_cast<__m128i*>(p), _mm512_cvtepi32_epi8(a.v));
}

inline F32 operator+(F32 a, F32 b) { return {_mm512_add_ps(a.v, b.v)}; }
inline F32 operator-(F32 a, F32 b) { return {_mm512_sub_ps(a.v, b.v)}; }
inline F32 operator*(F32 a, F32 b) { return {_mm512_mul_ps(a.v, b.v)}; }
inline F32 operator/(F32 a, F32 b) { return {_mm512_div_ps(a.v, b.v)}; }
inline F32 min(F32 a, F32 b) { return {_mm512_min_ps(a.v, b.v)}; }
inline F32 max(F32 a, F32 b) { return {_mm512_max_ps(a.v, b.v)}; }
inline F32 sqrt(F32 a) { return {_mm512_sqrt_ps(a.v)}; }
inline F32 floor(F32 a) { return {_mm512_roundscale_ps(a.v, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC)}; }
inline F32 toFloat(I32 a) { return {_mm512_cvtepi32_ps(a.v)}; }
inline I32 truncateToInt(F32 a) { return {_mm512_cvttps_epi32(a.v)}; }
inline F32 gather(const float* p, I32 index) { return {_mm512_i32gather_ps(index.v, p, 4)}; }

inline I32 operator+(I32 a, I32 b) { return {_mm512_add_epi32(a.v, b.v)}; }
inline I32 operator-(I32 a, I32 b) { return {_mm512_sub_epi32(a.v, b.v)}; }
inline I32 operator*(I32 a, I32 b) { return {_mm512_mullo_epi32(a.v, b.v)}; }
inline I32 operator&(I32 a, I32 b) { return {_mm512_and_si512(a.v, b.v)}; }
inline I32 operator|(I32 a, I32 b) { return {_mm512_or_si512(a.v, b.v)}; }
inline I32 operator^(I32 a, I32 b) { return {_mm512_xor_si512(a.v, b.v)}; }
inline I32 min(I32 a, I32 b) { return {_mm512_min_epi32(a.v, b.v)}; }
inline I32 max(I32 a, I32 b) { return {_mm512_max_epi32(a.v, b.v)}; }
template <int kBits> inline I32 shiftRight(I32 a) { return {_mm512_srai_epi32(a.v, kBits)}; }
template <int kBits> inline I32 shiftLeft(I32 a) { return {_mm512_slli_epi32(a.v, kBits)}; }

// Ordered compares are false on NaN and "not equal" is true on NaN, as in C++.
inline Mask cmpLt(F32 a, F32 b) { return {_mm512_cmp_ps_mask(a.v, b.v, _CMP_LT_OQ)}; }
inline Mask cmpLe(F32 a, F32 b) { return {_mm512_cmp_ps_mask(a.v, b.v, _CMP_LE_OQ)}; }
inline Mask cmpEq(F32 a, F32 b) { return {_mm512_cmp_ps_mask(a.v, b.v, _CMP_EQ_OQ)}; }
inline Mask cmpNe(F32 a, F32 b) { return {_mm512_cmp_ps_mask(a.v, b.v, _CMP_NEQ_UQ)}; }
inline Mask cmpGt(I32 a, I32 b) { return {_mm512_cmpgt_epi32_mask(a.v, b.v)}; }
inline Mask cmpEq(I32 a, I32 b) { return {_mm512_cmpeq_epi32_mask(a.v, b.v)}; }

inline Mask operator&(Mask a, Mask b) { return {__mmask16(a.v & b.v)}; }
inline Mask operator|(Mask a, Mask b) { return {__mmask16(a.v | b.v)}; }
inline Mask operator!(Mask a) { return {__mmask16(~a.v)}; }
inline Mask allLanes() { return {__mmask16(0xffff)}; }
inline Mask noLanes() { return {__mmask16(0)}; }
inline bool any(Mask a) { return a.v != 0; }
inline int countLanes(Mask a) { return __builtin_popcount(unsigned(a.v)); }

inline F32 select(Mask m, F32 a, F32 b) { return {_mm512_mask_blend_ps(m.v, b.v, a.v)}; }
inline I32 select(Mask m, I32 a, I32 b) { return {_mm512_mask_blend_epi32(m.v, b.v, a.v)}; }

// ---- Doubles, for exact work (setup, shadows/izb): kWidth64 lanes with their own mask ----
inline constexpr int kWidth64 = 8;
struct F64 { __m512d v; };
struct Mask64 { __mmask8 v; };

inline F64 splat64(double x) { return {_mm512_set1_pd(x)}; }
inline F64 load(const double* p) { return {_mm512_loadu_pd(p)}; }
inline F64 loadWidened(const float* p) { return {_mm512_cvtps_pd(_mm256_loadu_ps(p))}; }
inline F64 operator+(F64 a, F64 b) { return {_mm512_add_pd(a.v, b.v)}; }
inline F64 operator-(F64 a, F64 b) { return {_mm512_sub_pd(a.v, b.v)}; }
inline F64 operator*(F64 a, F64 b) { return {_mm512_mul_pd(a.v, b.v)}; }
inline F64 operator/(F64 a, F64 b) { return {_mm512_div_pd(a.v, b.v)}; }
inline F64 abs(F64 a) { return {_mm512_castsi512_pd(_mm512_andnot_si512(_mm512_set1_epi64(int64_t(1) << 63), _mm512_castpd_si512(a.v)))}; }
inline F64 max(F64 a, F64 b) { return {_mm512_max_pd(a.v, b.v)}; }
inline F64 min(F64 a, F64 b) { return {_mm512_min_pd(a.v, b.v)}; }
// Lane k of x, y, z from p[3k], p[3k + 1], p[3k + 2], widened: the 24 floats in two
// registers (the second load masked to 8, so it reads nothing past them), picked by two-
// source permutes (gathers are slow here).
inline void loadTriplesWidened(const float* p, F64& x, F64& y, F64& z) {
    const __m512 a = _mm512_loadu_ps(p), b = _mm512_maskz_loadu_ps(0x00ff, p + 16);
    const __m512i lanes = _mm512_setr_epi32(0, 3, 6, 9, 12, 15, 18, 21, 0, 0, 0, 0, 0, 0, 0, 0);
    const __m512i one = _mm512_set1_epi32(1);
    const __m512i lanesY = _mm512_add_epi32(lanes, one), lanesZ = _mm512_add_epi32(lanesY, one);
    x = {_mm512_cvtps_pd(_mm512_castps512_ps256(_mm512_permutex2var_ps(a, lanes, b)))};
    y = {_mm512_cvtps_pd(_mm512_castps512_ps256(_mm512_permutex2var_ps(a, lanesY, b)))};
    z = {_mm512_cvtps_pd(_mm512_castps512_ps256(_mm512_permutex2var_ps(a, lanesZ, b)))};
}
inline Mask64 nonZero64(const uint8_t* p) {
    return {_mm512_test_epi64_mask(_mm512_cvtepu8_epi64(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(p))),
                                   _mm512_set1_epi64(0xff))};
}
inline Mask64 operator|(Mask64 a, Mask64 b) { return {__mmask8(a.v | b.v)}; }
inline double reduceMin(F64 a) { return _mm512_reduce_min_pd(a.v); }
inline double reduceMax(F64 a) { return _mm512_reduce_max_pd(a.v); }
inline F64 sqrt(F64 a) { return {_mm512_sqrt_pd(a.v)}; }
inline F64 roundToFloat(F64 a) { return {_mm512_cvtps_pd(_mm512_cvtpd_ps(a.v))}; }
inline F64 floor(F64 a) { return {_mm512_roundscale_pd(a.v, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC)}; }
inline F64 powerOfTwo(F64 e) {
    const __m512d biased = _mm512_add_pd(e.v, _mm512_set1_pd(0x1.00000000003ffp52));
    return {_mm512_castsi512_pd(_mm512_slli_epi64(_mm512_castpd_si512(biased), 52))};
}
inline F64 binade(F64 a) {
    return {_mm512_castsi512_pd(_mm512_and_si512(_mm512_castpd_si512(a.v), _mm512_set1_epi64(0x7ff0000000000000ll)))};
}
inline void store(double* p, F64 a) { _mm512_storeu_pd(p, a.v); }
inline void storeNarrowed(float* p, F64 a) { _mm256_storeu_ps(p, _mm512_cvtpd_ps(a.v)); }
inline Mask64 cmpLt(F64 a, F64 b) { return {_mm512_cmp_pd_mask(a.v, b.v, _CMP_LT_OQ)}; }
inline Mask64 cmpLe(F64 a, F64 b) { return {_mm512_cmp_pd_mask(a.v, b.v, _CMP_LE_OQ)}; }
inline Mask64 cmpNe(F64 a, F64 b) { return {_mm512_cmp_pd_mask(a.v, b.v, _CMP_NEQ_UQ)}; }
inline Mask64 cmpEq(F64 a, F64 b) { return {_mm512_cmp_pd_mask(a.v, b.v, _CMP_EQ_OQ)}; }
inline Mask64 operator&(Mask64 a, Mask64 b) { return {__mmask8(a.v & b.v)}; }
inline Mask64 operator!(Mask64 a) { return {__mmask8(~a.v)}; }
// The first n lanes (n >= 0).
inline Mask64 firstLanes64(int n) { return {__mmask8(n >= 8 ? 0xff : (1u << n) - 1u)}; }
// Bit k set where lane k is true.
inline unsigned laneBits(Mask64 a) { return unsigned(a.v); }
inline F64 select(Mask64 m, F64 a, F64 b) { return {_mm512_mask_blend_pd(m.v, b.v, a.v)}; }

}  // namespace shadowlab::simd_avx512
