// Which decimal or double values a float can hold, shared by the file readers, and
// whether a vector's or matrix's every component is finite, for the checks of inputs.
#pragma once

#include <cmath>

#include <glm/glm.hpp>

namespace shadowlab {

// FLT_MAX plus half an ulp: from here on, rounding to float gives infinity. Testing in
// double first also avoids converting an out-of-range double, which C++ leaves undefined.
inline constexpr double kFloatOverflow = 0x1.ffffffp127;

inline bool roundsToFiniteFloat(double x) {
    return std::abs(x) < kFloatOverflow;   // false for NaN as well
}

template <glm::length_t N, class T, glm::qualifier Q>
bool allFinite(const glm::vec<N, T, Q>& v) {
    for (glm::length_t k = 0; k < N; ++k) {
        if (!std::isfinite(v[k])) return false;
    }
    return true;
}

template <glm::length_t C, glm::length_t R, class T, glm::qualifier Q>
bool allFinite(const glm::mat<C, R, T, Q>& m) {
    for (glm::length_t c = 0; c < C; ++c) {
        if (!allFinite(m[c])) return false;
    }
    return true;
}

}  // namespace shadowlab
