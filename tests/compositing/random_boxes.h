// Random vectors and axis-aligned boxes for the tests of differential rendering.
#pragma once

#include <random>
#include <vector>

#include "scenes/bounds.h"

namespace shadowlab::test {

// Three draws in order, x first: the arguments of one call would be drawn in an order that
// differs between compilers (GCC right to left, Clang left to right), and so would the tests.
template <class Distribution>
glm::dvec3 randomVector(Distribution& d, std::mt19937_64& rng) {
    const double x = d(rng);
    const double y = d(rng);
    const double z = d(rng);
    return {x, y, z};
}

// `count` boxes whose centres are uniform in the box [lo, hi] and whose half-sizes are
// uniform in [0, halfSize] on each axis.
inline std::vector<Aabb> randomBoxes(std::mt19937_64& rng, int count, glm::dvec3 lo, glm::dvec3 hi, double halfSize) {
    std::uniform_real_distribution<double> t(0.0, 1.0), half(0.0, halfSize);
    std::vector<Aabb> boxes;
    for (int k = 0; k < count; ++k) {
        const glm::dvec3 c = lo + (hi - lo) * randomVector(t, rng);
        const glm::dvec3 h = randomVector(half, rng);
        boxes.push_back({c - h, c + h});
    }
    return boxes;
}

inline bool contains(const Aabb& outer, const Aabb& inner) {
    return glm::all(glm::lessThanEqual(outer.min, inner.min)) && glm::all(glm::lessThanEqual(inner.max, outer.max));
}

}  // namespace shadowlab::test
