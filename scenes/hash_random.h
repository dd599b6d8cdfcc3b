// Random numbers without state for procedural content: the value for (seed, index) is a
// pure function of the two, so a mesh or a volume is the same bytes however and in whatever
// order it is built. The mixer is SplitMix64's finaliser (Steele, Lea and Flood, "Fast
// splittable pseudorandom number generators", OOPSLA 2014), a bijection of 64-bit words
// whose output passes BigCrush.
#pragma once

#include <cstdint>

namespace shadowlab {

inline uint64_t mix64(uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

// A double in [0, 1) from the top 53 bits of the mixed (seed, index).
inline double unitHash(uint64_t seed, uint64_t index) {
    return double(mix64(seed * 0x9e3779b97f4a7c15ull + mix64(index)) >> 11) * 0x1.0p-53;
}

}  // namespace shadowlab
