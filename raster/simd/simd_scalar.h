// One-lane "SIMD" types: the scalar reference twin of simd_avx2.h and simd_avx512.h.
// The rasterizer's tile kernel is written once against this interface; compiled with
// these types it is the plain C++ reference that the vector paths are held to, bit for
// bit (tests/raster/test_determinism.cpp). Every operation is the IEEE operation of the
// same name on each lane, with no FMA and no approximations, so all three agree exactly.
#pragma once

#include <cstdint>

namespace shadowlab::simd_scalar {

inline constexpr int kWidth = 1;

struct F32 { float v; };
struct I32 { int32_t v; };
struct Mask { bool v; };

inline F32 splat(float x) { return {x}; }
inline I32 splat(int32_t x) { return {x}; }
inline I32 laneIndex() { return {0}; }

inline F32 load(const float* p) { return {*p}; }
inline I32 load(const uint32_t* p) { return {int32_t(*p)}; }
inline I32 loadU8(const uint8_t* p) { return {int32_t(*p)}; }
// Lane k of x, y, z from p[3k], p[3k + 1], p[3k + 2] (a run of x, y, z triples).
inline void loadTriples(const float* p, F32& x, F32& y, F32& z) { x = {p[0]}, y = {p[1]}, z = {p[2]}; }
inline void store(float* p, F32 a) { *p = a.v; }
inline void store(uint32_t* p, I32 a) { *p = uint32_t(a.v); }
inline void storeU8(uint8_t* p, I32 a) { *p = uint8_t(a.v); }

inline F32 operator+(F32 a, F32 b) { return {a.v + b.v}; }
inline F32 operator-(F32 a, F32 b) { return {a.v - b.v}; }
inline F32 operator*(F32 a, F32 b) { return {a.v * b.v}; }
inline F32 operator/(F32 a, F32 b) { return {a.v / b.v}; }
// As minps/maxps: the second operand when the lanes are unordered or both zero.
inline F32 min(F32 a, F32 b) { return {a.v < b.v ? a.v : b.v}; }
inline F32 max(F32 a, F32 b) { return {a.v > b.v ? a.v : b.v}; }
inline F32 sqrt(F32 a) { return {__builtin_sqrtf(a.v)}; }
inline F32 floor(F32 a) { return {__builtin_floorf(a.v)}; }
inline F32 toFloat(I32 a) { return {float(a.v)}; }
// Rounds towards zero; lanes must hold values an int32 can (callers saturate first).
inline I32 truncateToInt(F32 a) { return {int32_t(a.v)}; }
// p[index], lane by lane.
inline F32 gather(const float* p, I32 index) { return {p[index.v]}; }

inline I32 operator+(I32 a, I32 b) { return {a.v + b.v}; }
inline I32 operator-(I32 a, I32 b) { return {a.v - b.v}; }
inline I32 operator*(I32 a, I32 b) { return {a.v * b.v}; }
inline I32 operator&(I32 a, I32 b) { return {a.v & b.v}; }
inline I32 operator|(I32 a, I32 b) { return {a.v | b.v}; }
inline I32 operator^(I32 a, I32 b) { return {a.v ^ b.v}; }
inline I32 min(I32 a, I32 b) { return {a.v < b.v ? a.v : b.v}; }
inline I32 max(I32 a, I32 b) { return {a.v > b.v ? a.v : b.v}; }
template <int kBits> inline I32 shiftRight(I32 a) { return {a.v >> kBits}; }
template <int kBits> inline I32 shiftLeft(I32 a) { return {int32_t(uint32_t(a.v) << kBits)}; }

// Comparisons return masks, so they are named functions rather than operators.
inline Mask cmpLt(F32 a, F32 b) { return {a.v < b.v}; }
inline Mask cmpLe(F32 a, F32 b) { return {a.v <= b.v}; }
inline Mask cmpEq(F32 a, F32 b) { return {a.v == b.v}; }
inline Mask cmpNe(F32 a, F32 b) { return {a.v != b.v}; }
inline Mask cmpGt(I32 a, I32 b) { return {a.v > b.v}; }
inline Mask cmpEq(I32 a, I32 b) { return {a.v == b.v}; }

inline Mask operator&(Mask a, Mask b) { return {a.v && b.v}; }
inline Mask operator|(Mask a, Mask b) { return {a.v || b.v}; }
inline Mask operator!(Mask a) { return {!a.v}; }
inline Mask allLanes() { return {true}; }
inline Mask noLanes() { return {false}; }
inline bool any(Mask a) { return a.v; }
inline int countLanes(Mask a) { return a.v ? 1 : 0; }

inline F32 select(Mask m, F32 a, F32 b) { return m.v ? a : b; }
inline I32 select(Mask m, I32 a, I32 b) { return m.v ? a : b; }

// ---- Doubles, for exact work (setup, shadows/izb): kWidth64 lanes with their own mask ----
inline constexpr int kWidth64 = 1;
struct F64 { double v; };
struct Mask64 { bool v; };

inline F64 splat64(double x) { return {x}; }
inline F64 load(const double* p) { return {*p}; }
inline F64 loadWidened(const float* p) { return {double(*p)}; }
inline F64 operator+(F64 a, F64 b) { return {a.v + b.v}; }
inline F64 operator-(F64 a, F64 b) { return {a.v - b.v}; }
inline F64 operator*(F64 a, F64 b) { return {a.v * b.v}; }
inline F64 operator/(F64 a, F64 b) { return {a.v / b.v}; }
inline F64 abs(F64 a) { return {__builtin_fabs(a.v)}; }
// As maxpd: the second operand when the lanes are unordered or both zero.
inline F64 max(F64 a, F64 b) { return {a.v > b.v ? a.v : b.v}; }
inline F64 min(F64 a, F64 b) { return {a.v < b.v ? a.v : b.v}; }
// Lane k of x, y, z from the floats p[3k], p[3k + 1], p[3k + 2], widened.
inline void loadTriplesWidened(const float* p, F64& x, F64& y, F64& z) { x = {p[0]}, y = {p[1]}, z = {p[2]}; }
// Lanes where p[k] != 0.
inline Mask64 nonZero64(const uint8_t* p) { return {*p != 0}; }
inline Mask64 operator|(Mask64 a, Mask64 b) { return {a.v || b.v}; }
// The smallest and the largest lane.
inline double reduceMin(F64 a) { return a.v; }
inline double reduceMax(F64 a) { return a.v; }
inline F64 sqrt(F64 a) { return {__builtin_sqrt(a.v)}; }
// Rounded to the nearest float and widened back: the value a float variable would hold.
inline F64 roundToFloat(F64 a) { return {double(float(a.v))}; }
inline F64 floor(F64 a) { return {__builtin_floor(a.v)}; }
// 2^e for integral lanes -1022 <= e <= 1023: e + (2^52 + 1023) is exact and holds e + 1023
// in its low mantissa bits, which a shift moves into the exponent field.
inline F64 powerOfTwo(F64 e) {
    return {__builtin_bit_cast(double, __builtin_bit_cast(uint64_t, e.v + 0x1.00000000003ffp52) << 52)};
}
// 2^e for a = m 2^e, 1 <= |m| < 2 (a normal, positive): a with its mantissa bits cleared.
inline F64 binade(F64 a) {
    return {__builtin_bit_cast(double, __builtin_bit_cast(uint64_t, a.v) & 0x7ff0000000000000ull)};
}
inline void store(double* p, F64 a) { *p = a.v; }
// Each lane rounded to the nearest float, as float(x) does.
inline void storeNarrowed(float* p, F64 a) { *p = float(a.v); }
inline Mask64 cmpLt(F64 a, F64 b) { return {a.v < b.v}; }
inline Mask64 cmpLe(F64 a, F64 b) { return {a.v <= b.v}; }
inline Mask64 cmpNe(F64 a, F64 b) { return {a.v != b.v}; }
inline Mask64 cmpEq(F64 a, F64 b) { return {a.v == b.v}; }
inline Mask64 operator&(Mask64 a, Mask64 b) { return {a.v && b.v}; }
inline Mask64 operator!(Mask64 a) { return {!a.v}; }
// The first n lanes (n >= 0).
inline Mask64 firstLanes64(int n) { return {n > 0}; }
// Bit k set where lane k is true.
inline unsigned laneBits(Mask64 a) { return a.v ? 1u : 0u; }
inline F64 select(Mask64 m, F64 a, F64 b) { return m.v ? a : b; }

}  // namespace shadowlab::simd_scalar
