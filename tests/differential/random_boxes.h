// Random vectors and axis-aligned boxes for the tests of differential rendering, and the
// slab test of a segment against a box.
#pragma once

#include <algorithm>
#include <random>
#include <utility>
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

// The slab test: does the segment p -> q pass through the box?
inline bool segmentHitsBox(const glm::dvec3& p, const glm::dvec3& q, const Aabb& box) {
    double t0 = 0.0, t1 = 1.0;
    for (int axis = 0; axis < 3; ++axis) {
        const double d = q[axis] - p[axis];
        if (d == 0.0) {
            if (p[axis] < box.min[axis] || p[axis] > box.max[axis]) return false;
            continue;
        }
        double a = (box.min[axis] - p[axis]) / d, b = (box.max[axis] - p[axis]) / d;
        if (a > b) std::swap(a, b);
        t0 = std::max(t0, a), t1 = std::min(t1, b);
        if (t0 > t1) return false;
    }
    return true;
}

inline bool contains(const Aabb& outer, const Aabb& inner) {
    return glm::all(glm::lessThanEqual(outer.min, inner.min)) && glm::all(glm::lessThanEqual(inner.max, outer.max));
}

}  // namespace shadowlab::test
