// Random axis-aligned boxes for the tests of the differential-rendering hierarchies.
#pragma once

#include <random>
#include <vector>

#include "scenes/bounds.h"

namespace shadowlab::test {

// `count` boxes whose centres are uniform in the box [lo, hi] and whose half-sizes are
// uniform in [0, halfSize] on each axis.
inline std::vector<Aabb> randomBoxes(std::mt19937_64& rng, int count, glm::dvec3 lo, glm::dvec3 hi, double halfSize) {
    std::uniform_real_distribution<double> t(0.0, 1.0), half(0.0, halfSize);
    std::vector<Aabb> boxes;
    for (int k = 0; k < count; ++k) {
        const glm::dvec3 c = lo + (hi - lo) * glm::dvec3(t(rng), t(rng), t(rng)), h(half(rng), half(rng), half(rng));
        boxes.push_back({c - h, c + h});
    }
    return boxes;
}

inline bool contains(const Aabb& outer, const Aabb& inner) {
    return glm::all(glm::lessThanEqual(outer.min, inner.min)) && glm::all(glm::lessThanEqual(inner.max, outer.max));
}

}  // namespace shadowlab::test
