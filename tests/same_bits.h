// Bit-for-bit equality of doubles (so -0 differs from +0, and a NaN can equal itself), for
// the tests that hold a SIMD kernel to its scalar twin.
#pragma once

#include <cstring>

namespace shadowlab::test {

inline bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace shadowlab::test
