// Elementary functions that give the same bits on every x86-64 CPU (docs/determinism.md).
//
// glibc picks among several builds of exp, log, pow, sin, cos, tan and acos at run time
// (with or without FMA, AVX2) and they differ in the last bit for some arguments: set
// GLIBC_TUNABLES=glibc.cpu.hwcaps=-AVX2,-FMA and their results change. Every value that
// reaches an output (procedural meshes, transforms, projections, Poisson rotations,
// moment warps, cascade splits, fin arcs, shading) is computed here instead: a fixed
// sequence of IEEE double additions, multiplications and divisions (the project compiles
// with -ffp-contract=off), with exact scaling by powers of two, so the bits depend only on
// the argument. The methods are the textbook ones (Muller, "Elementary Functions", 2016,
// ch. 11): reduce the argument by an exactly representable split of the period (Cody and
// Waite 1980), then sum a Taylor series far enough that its truncation lies below half an
// ulp. tests/raster/test_portable_math.cpp holds each within a few ulps of libm.
//
// Arguments are those of geometry and shading: sin, cos and tan are reduced with a two-part
// pi/2 that is exact for |x| < 2^20 (beyond, the result loses accuracy, never determinism).
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>

#include "raster/portable_constants.h"

namespace shadowlab::portable {

namespace detail {

// 2^e for a normal exponent, -1022 <= e <= 1023: its biased exponent in the bits.
inline double powerOfTwo(int e) { return __builtin_bit_cast(double, uint64_t(e + 1023) << 52); }

// sin and cos of r, |r| <= pi/4: Taylor to r^21 and r^22 (truncation below 1e-22).
inline double sinReduced(double r) {
    const double r2 = r * r;
    double sum = 0.0;
    for (int n = 21; n >= 3; n -= 2) sum = (sum + ((n / 2) % 2 ? -1.0 : 1.0) * kInverseFactorial.value[n]) * r2;
    return r + r * sum;
}
inline double cosReduced(double r) {
    const double r2 = r * r;
    double sum = 0.0;
    for (int n = 22; n >= 2; n -= 2) sum = (sum + ((n / 2) % 2 ? -1.0 : 1.0) * kInverseFactorial.value[n]) * r2;
    return 1.0 + sum;
}

// x = k pi/2 + r with |r| <= pi/4 (about); returns r and sets the quadrant k mod 4.
inline double reduceHalfPi(double x, int& quadrant) {
    const double k = std::floor(x * kTwoOverPi + 0.5);
    quadrant = int(std::fmod(k, 4.0) + 4.0) % 4;
    return (x - k * kHalfPiHigh) - k * kHalfPiLow;
}

// atan(u) for |u| <= tan(pi/12): Taylor to u^31 (truncation below 1e-19).
inline double atanReduced(double u) {
    const double u2 = u * u;
    double sum = 0.0;
    for (int n = 31; n >= 3; n -= 2) sum = (sum + ((n / 2) % 2 ? -1.0 : 1.0) / n) * u2;
    return u + u * sum;
}

// sin(x + turns pi/2): the reduced argument's sine or cosine, by quadrant.
inline double sinQuarterTurns(double x, int turns) {
    if (!std::isfinite(x)) return std::numeric_limits<double>::quiet_NaN();
    int quadrant;
    const double r = reduceHalfPi(x, quadrant);
    switch ((quadrant + turns) % 4) {
        case 0: return sinReduced(r);
        case 1: return cosReduced(r);
        case 2: return -sinReduced(r);
        default: return -cosReduced(r);
    }
}
}  // namespace detail

inline double sin(double x) { return detail::sinQuarterTurns(x, 0); }
inline double cos(double x) { return detail::sinQuarterTurns(x, 1); }

inline double tan(double x) { return sin(x) / cos(x); }

// e^x: x = k ln 2 + r, |r| <= ln 2 / 2, Taylor to r^16, scaled by 2^k exactly.
inline double exp(double x) {
    if (std::isnan(x)) return x;
    if (x > detail::kExpOverflow) return std::numeric_limits<double>::infinity();
    if (x < detail::kExpUnderflow) return 0.0;
    const double k = std::floor(x * detail::kInvLn2 + 0.5);
    const double r = (x - k * detail::kLn2High) - k * detail::kLn2Low;
    double sum = detail::kInverseFactorial.value[16];
    for (int n = 15; n >= 0; --n) sum = sum * r + detail::kInverseFactorial.value[n];
    // Two steps of 2^(k/2): 2^k alone may not be a double near the ends of the range. Each
    // factor is a normal power of two (|k / 2| <= 538), so the first product is exact and
    // the second rounds once, as ldexp does, without ldexp's library call.
    const int half = int(k) / 2;
    return (sum * detail::powerOfTwo(half)) * detail::powerOfTwo(int(k) - half);
}

// ln x: x = m 2^e with m in [sqrt(1/2), sqrt(2)), ln m = 2 atanh(s) with s = (m-1)/(m+1),
// |s| <= 0.172, summed to s^23. Powers of two give exactly e ln 2 in log2.
namespace detail {
inline double logOfMantissa(double x, int& exponent) {
    double m = std::frexp(x, &exponent);
    if (m < 0.7071067811865476) m *= 2.0, --exponent;
    const double s = (m - 1.0) / (m + 1.0), s2 = s * s;
    double sum = 0.0;
    for (int n = 23; n >= 3; n -= 2) sum = (sum + 1.0 / n) * s2;
    return 2.0 * (s + s * sum);
}

// log and log2 of NaN, negative, zero and infinite x, as libm gives them; false for a
// positive finite x.
inline bool logOfSpecial(double x, double& result) {
    if (std::isnan(x) || x < 0.0) result = std::numeric_limits<double>::quiet_NaN();
    else if (x == 0.0) result = -std::numeric_limits<double>::infinity();
    else if (std::isinf(x)) result = x;
    else return false;
    return true;
}
}  // namespace detail

inline double log(double x) {
    if (double special; detail::logOfSpecial(x, special)) return special;
    int e;
    const double lnM = detail::logOfMantissa(x, e);
    return e * detail::kLn2High + (lnM + e * detail::kLn2Low);
}

inline double log2(double x) {
    if (double special; detail::logOfSpecial(x, special)) return special;
    int e;
    const double lnM = detail::logOfMantissa(x, e);
    return e + lnM * detail::kInvLn2;
}

// 2^x = 2^k e^{f ln 2} with k the nearest integer: exact for integral x.
inline double exp2(double x) {
    if (std::isnan(x)) return x;
    if (x > 1024.0) return std::numeric_limits<double>::infinity();
    if (x < -1075.0) return 0.0;
    const double k = std::floor(x + 0.5);
    return std::ldexp(exp((x - k) * detail::kLn2), int(k));
}

// a^b for a >= 0 as e^{b ln a} (relative error about |b ln a| ulps, ample for exponents of
// shading and splits); a < 0 gives NaN, as std::pow does for non-integral b.
inline double pow(double a, double b) {
    if (b == 0.0) return 1.0;
    if (a == 0.0) return b > 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
    return exp(b * log(a));
}

// a^b for a float a >= 0 to a float's precision, for per-pixel exponents (FLIP's, about ten a
// pixel): pow's reductions with series cut where their truncation falls below 1e-11, a
// thousandth of a float ulp, and no library call (the exponent read from the bits). Positive
// normal or zero a; a < 0 or NaN gives NaN.
inline float powFloat(float a, float b) {
    if (b == 0.0f) return 1.0f;
    if (!(a >= 0.0f)) return std::numeric_limits<float>::quiet_NaN();
    if (a == 0.0f) return b > 0.0f ? 0.0f : std::numeric_limits<float>::infinity();
    // ln a: a = m 2^e, m in [sqrt(1/2), sqrt(2)), ln m = 2 atanh(s), s = (m - 1)/(m + 1), to s^11.
    const uint64_t bits = __builtin_bit_cast(uint64_t, double(a));
    int e = int(bits >> 52) - 1023;
    double m = __builtin_bit_cast(double, (bits & 0x000fffffffffffffull) | 0x3ff0000000000000ull);
    if (m > 1.4142135623730951) m *= 0.5, ++e;
    const double s = (m - 1.0) / (m + 1.0), s2 = s * s;
    double series = 0.0;
    for (int n = 11; n >= 3; n -= 2) series = (series + 1.0 / n) * s2;
    const double y = double(b) * (e * detail::kLn2 + 2.0 * (s + s * series));
    // e^y: y = k ln 2 + r, |r| <= ln 2 / 2, Taylor to r^10 (truncation 2e-13).
    if (y > 710.0) return std::numeric_limits<float>::infinity();
    if (y < -745.0) return 0.0f;
    const double k = std::floor(y * detail::kInvLn2 + 0.5);
    const double r = (y - k * detail::kLn2High) - k * detail::kLn2Low;
    double sum = detail::kInverseFactorial.value[10];
    for (int n = 9; n >= 0; --n) sum = sum * r + detail::kInverseFactorial.value[n];
    const int half = int(k) / 2;
    return float((sum * detail::powerOfTwo(half)) * detail::powerOfTwo(int(k) - half));
}

// atan by the symmetries atan(x) = pi/2 - atan(1/x) and atan(t) = pi/6 + atan((t sqrt 3 - 1) /
// (t + sqrt 3)), which bring the argument within tan(pi/12).
inline double atan(double x) {
    if (std::isnan(x)) return x;
    const double t = std::abs(x);
    const bool inverted = t > 1.0;
    double u = inverted ? 1.0 / t : t;
    double offset = 0.0;
    if (u > detail::kTanTwelfthPi) {
        u = (u * detail::kSqrt3 - 1.0) / (u + detail::kSqrt3);
        offset = detail::kSixthPi;
    }
    double angle = offset + detail::atanReduced(u);
    if (inverted) angle = detail::kHalfPi - angle;
    return std::signbit(x) ? -angle : angle;   // atan(-0) = -0
}

// acos x = 2 atan(sqrt((1 - x) / (1 + x))); NaN outside [-1, 1].
inline double acos(double x) {
    if (!(x >= -1.0 && x <= 1.0)) return std::numeric_limits<double>::quiet_NaN();
    if (x == -1.0) return detail::kPi;
    return 2.0 * atan(std::sqrt((1.0 - x) / (1.0 + x)));
}

// atan2(y, x) in [-pi, pi]: the angle in the first quadrant from atan of the ratio that is at
// most 1 (pi/2 - atan of the other), then reflected by the signs, so atan2(+-0, -0) = +-pi
// and atan2(+-0, +0) = +-0 as in libm.
inline double atan2(double y, double x) {
    if (std::isnan(x) || std::isnan(y)) return std::numeric_limits<double>::quiet_NaN();
    const double ax = std::abs(x), ay = std::abs(y);
    double angle;
    if (std::isinf(ax) && std::isinf(ay)) {
        angle = 0.5 * detail::kHalfPi;
    } else if (ax >= ay) {
        angle = ax == 0.0 ? 0.0 : atan(ay / ax);
    } else {
        angle = detail::kHalfPi - atan(ax / ay);
    }
    if (std::signbit(x)) angle = detail::kPi - angle;
    return std::signbit(y) ? -angle : angle;
}

// sqrt(a^2 + b^2) (sqrt is correctly rounded by IEEE 754; no overflow at scene scales).
inline double hypot(double a, double b) { return std::sqrt(a * a + b * b); }

}  // namespace shadowlab::portable
