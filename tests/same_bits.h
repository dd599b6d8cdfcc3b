// Bit-for-bit equality, for the tests that hold a SIMD kernel to its scalar twin or a
// buffer to its copy: doubles (so -0 differs from +0, and a NaN can equal itself) and
// arrays of plain values, byte by byte.
#pragma once

#include <cstring>
#include <vector>

namespace shadowlab::test {

inline bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

template <class T>
bool sameBytes(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

}  // namespace shadowlab::test
