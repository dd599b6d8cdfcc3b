// Directions spread evenly over the sphere for the environment tests: a Fibonacci lattice.
#pragma once

#include <cmath>
#include <vector>

#include <glm/glm.hpp>

inline std::vector<glm::dvec3> sphereDirections(int n) {
    std::vector<glm::dvec3> d;
    for (int k = 0; k < n; ++k) {
        const double y = 1.0 - (2.0 * k + 1.0) / n, r = std::sqrt(1.0 - y * y), phi = 2.399963229728653 * k;
        d.push_back({r * std::cos(phi), y, r * std::sin(phi)});
    }
    return d;
}
