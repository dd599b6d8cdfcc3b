// The constants of portable_math.h: plain data, so that the per-instruction-set kernels
// (portable_exp.inl) can share them without including any inline function.
#pragma once

#include <cstdint>

namespace shadowlab::portable::detail {

// pi/2 = kHalfPiHigh + kHalfPiLow, the high part with 33 significant bits so that
// k * kHalfPiHigh is exact for |k| < 2^20; ln 2 likewise with 32 bits.
inline constexpr double kHalfPiHigh = 0x1.921fb544p+0;
inline constexpr double kHalfPiLow = 0x1.0b4611a626331p-34;
inline constexpr double kTwoOverPi = 0.6366197723675814;
inline constexpr double kLn2High = 0x1.62e42feep-1;
inline constexpr double kLn2Low = 0x1.a39ef35793c76p-33;
inline constexpr double kLn2 = 0.6931471805599453;
inline constexpr double kInvLn2 = 1.4426950408889634;
inline constexpr double kPi = 3.141592653589793;
inline constexpr double kHalfPi = 1.5707963267948966;
inline constexpr double kSixthPi = 0.5235987755982989;
inline constexpr double kSqrt3 = 1.7320508075688772;
inline constexpr double kTanTwelfthPi = 0.2679491924311227;   // 2 - sqrt(3)

// 1/n! for n = 0..22, computed by the compiler in IEEE double (n! is exact up to 18!), so
// the same constants on every machine.
struct InverseFactorials {
    double value[23];
    constexpr InverseFactorials() : value() {
        double factorial = 1.0;
        for (int n = 0; n < 23; ++n) {
            if (n > 0) factorial *= n;
            value[n] = 1.0 / factorial;
        }
    }
};
inline constexpr InverseFactorials kInverseFactorial{};

// e^x overflows above this and is 0 below this (the largest double is about e^709.78, the
// smallest subnormal e^-745.13).
inline constexpr double kExpOverflow = 709.782712893384;
inline constexpr double kExpUnderflow = -745.1332191019412;

}  // namespace shadowlab::portable::detail

namespace shadowlab {

// pi, for every layer: one name for the concept (portable_math.h's own constant).
inline constexpr double kPi = portable::detail::kPi;

}  // namespace shadowlab
