// Which decimal or double values a float can hold, shared by the file readers.
#pragma once

#include <cmath>

namespace shadowlab {

// FLT_MAX plus half an ulp: from here on, rounding to float gives infinity. Testing in
// double first also avoids converting an out-of-range double, which C++ leaves undefined.
inline constexpr double kFloatOverflow = 0x1.ffffffp127;

inline bool roundsToFiniteFloat(double x) {
    return std::abs(x) < kFloatOverflow;   // false for NaN as well
}

}  // namespace shadowlab
