// The form factor from a differential area to a polygon (shading/form_factor.h) against
// the analytic cases of the radiosity catalogues, derived here from the area integral
// F = 1 / pi * integral of cos t_x cos t_y / r^2 over the polygon, and against that
// integral by the midpoint rule where no closed form is at hand (a patch across the
// receiver's horizon, a tilted parallelogram).
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "raster/portable_constants.h"
#include "shading/form_factor.h"

using namespace shadowlab;

namespace {

struct Box {
    double a, b, c;   // the rectangle's sides and its distance
};

// The rectangle origin + s u + t v, s in [0, a], t in [0, b], counter-clockwise seen from
// the side u x v points to.
std::vector<glm::dvec3> rectangle(glm::dvec3 origin, glm::dvec3 u, glm::dvec3 v, double a, double b) {
    return {origin, origin + a * u, origin + a * u + b * v, origin + b * v};
}

std::vector<glm::dvec3> reversed(std::vector<glm::dvec3> p) { return {p.rbegin(), p.rend()}; }

// The area integral by the midpoint rule on an m x m grid of the parallelogram
// origin + s u + t v (s, t in [0, 1]).
double areaIntegral(const glm::dvec3& x, const glm::dvec3& n, glm::dvec3 origin, glm::dvec3 u, glm::dvec3 v, int m = 1000) {
    const glm::dvec3 normal = glm::normalize(glm::cross(u, v));
    const double cell = glm::length(glm::cross(u, v)) / double(m) / double(m);
    double sum = 0.0;
    for (int i = 0; i < m; ++i) {
        for (int j = 0; j < m; ++j) {
            const double s = (i + 0.5) / m, t = (j + 0.5) / m;
            const glm::dvec3 d = origin + s * u + t * v - x;
            const double r2 = glm::dot(d, d), r = std::sqrt(r2);
            const double cosX = std::max(0.0, glm::dot(n, d) / r), cosY = std::max(0.0, -glm::dot(normal, d) / r);
            sum += cosX * cosY / (kPi * r2) * cell;
        }
    }
    return sum;
}

}  // namespace

// Receiver at the origin facing +z; an a x b rectangle at height c facing down, one
// corner above the receiver: F = 1/2pi [A/sqrt(1+A^2) atan(B/sqrt(1+A^2)) + B/sqrt(1+B^2)
// atan(A/sqrt(1+B^2))], A = a/c, B = b/c (integrating c^2 / (pi (x^2+y^2+c^2)^2)).
TEST_CASE("form factor: a rectangle parallel to the receiver, a corner above it, is the catalogue's") {
    for (const Box& k : {Box{1.0, 1.0, 1.0}, Box{2.0, 0.5, 1.5}, Box{10.0, 10.0, 0.1}, Box{0.1, 0.2, 5.0}}) {
        const double a = k.a, b = k.b, c = k.c, A = a / c, B = b / c;
        const double expected = (A / std::sqrt(1 + A * A) * std::atan(B / std::sqrt(1 + A * A)) +
                                 B / std::sqrt(1 + B * B) * std::atan(A / std::sqrt(1 + B * B))) / (2.0 * kPi);
        // Facing down: counter-clockwise seen from below.
        const auto patch = rectangle({0, 0, c}, {0, 1, 0}, {1, 0, 0}, b, a);
        INFO("a = " << k.a << ", b = " << k.b << ", c = " << k.c);
        CHECK(pointToPolygonFormFactor({0, 0, 0}, {0, 0, 1}, patch) == doctest::Approx(expected).epsilon(1e-12));
        // Facing up, the receiver is behind the emitter: nothing.
        CHECK(pointToPolygonFormFactor({0, 0, 0}, {0, 0, 1}, reversed(patch)) == 0.0);
    }
    // Four such rectangles around the axis make one centred on it: F grows to 1 as it covers the sky.
    const double big = pointToPolygonFormFactor({0, 0, 0}, {0, 0, 1}, rectangle({-1e4, -1e4, 1}, {0, 1, 0}, {1, 0, 0}, 2e4, 2e4));
    CHECK(big == doctest::Approx(1.0).epsilon(1e-4));
    CHECK(big <= 1.0);
}

// Receiver at the origin facing +z; a rectangle in the plane y = b facing -y, x in [0, a],
// z in [0, c]: F = 1/pi int int z b / (x^2+b^2+z^2)^2 dz dx
//               = 1/2pi [atan X - 1/sqrt(1+Y^2) atan(X / sqrt(1+Y^2))], X = a/b, Y = c/b.
TEST_CASE("form factor: a rectangle perpendicular to the receiver, an edge on its plane, is the closed form") {
    for (const Box& k : {Box{1.0, 1.0, 1.0}, Box{3.0, 0.5, 2.0}, Box{0.2, 2.0, 0.1}, Box{50.0, 1.0, 50.0}}) {
        const double a = k.a, b = k.b, c = k.c, X = a / b, Y = c / b;
        const double expected = (std::atan(X) - std::atan(X / std::sqrt(1 + Y * Y)) / std::sqrt(1 + Y * Y)) / (2.0 * kPi);
        const auto patch = rectangle({0, b, 0}, {1, 0, 0}, {0, 0, 1}, a, c);   // x cross z = -y: faces the receiver
        INFO("a = " << k.a << ", b = " << k.b << ", c = " << k.c);
        CHECK(pointToPolygonFormFactor({0, 0, 0}, {0, 0, 1}, patch) == doctest::Approx(expected).epsilon(1e-12));
        // Below the horizon (z in [-c, 0]) the receiver sees none of it.
        CHECK(pointToPolygonFormFactor({0, 0, 0}, {0, 0, 1}, rectangle({0, b, -c}, {1, 0, 0}, {0, 0, 1}, a, c)) == 0.0);
    }
}

TEST_CASE("form factor: a patch across the receiver's horizon counts above it only, as the area integral does") {
    const glm::dvec3 x(0.3, -0.2, 0.0), n = glm::normalize(glm::dvec3(0.2, 0.1, 1.0));
    // A wall facing the receiver, from below its tangent plane to above it.
    const glm::dvec3 origin(-1.0, 1.5, -1.0), u(2.5, 0.0, 0.0), v(0.0, 0.3, 3.0);
    const std::vector<glm::dvec3> wall{origin, origin + u, origin + u + v, origin + v};
    const double expected = areaIntegral(x, n, origin, u, v);
    CHECK(expected > 0.01);
    CHECK(pointToPolygonFormFactor(x, n, wall) == doctest::Approx(expected).epsilon(1e-5));
    // A tilted parallelogram, wholly above; split along a diagonal, its two triangles add
    // up to it (the contour integral is additive over shared edges).
    const glm::dvec3 t0(-0.5, 0.4, 1.2), tu(1.4, 0.3, 0.6), tv(0.2, 1.1, -0.3);
    const bool facing = glm::dot(glm::cross(tu, tv), x - t0) > 0.0;
    const glm::dvec3 first = facing ? tu : tv, second = facing ? tv : tu;
    const std::vector<glm::dvec3> quad{t0, t0 + first, t0 + first + second, t0 + second};
    const double F = pointToPolygonFormFactor(x, n, quad);
    CHECK(F == doctest::Approx(areaIntegral(x, n, t0, first, second)).epsilon(1e-5));
    const std::vector<glm::dvec3> lower{quad[0], quad[1], quad[2]}, upper{quad[0], quad[2], quad[3]};
    CHECK(pointToPolygonFormFactor(x, n, lower) + pointToPolygonFormFactor(x, n, upper) == doctest::Approx(F).epsilon(1e-12));
}

TEST_CASE("form factor: degenerate polygons and receivers in the polygon's plane give 0") {
    const auto patch = rectangle({0, 0, 1}, {0, 1, 0}, {1, 0, 0}, 1.0, 1.0);
    CHECK(pointToPolygonFormFactor({0.5, 0.5, 1.0}, {0, 0, 1}, patch) == 0.0);   // in its plane
    CHECK(pointToPolygonFormFactor({0, 0, 0}, {0, 0, 1}, std::vector<glm::dvec3>{{0, 0, 1}, {1, 0, 1}}) == 0.0);
    CHECK(pointToPolygonFormFactor({0, 0, 0}, {0, 0, 1}, std::vector<glm::dvec3>{{0, 0, 1}, {1, 0, 1}, {2, 0, 1}}) == 0.0);
    // Facing away from the patch: the receiver's horizon hides it.
    CHECK(pointToPolygonFormFactor({0, 0, 0}, {0, 0, -1}, patch) == 0.0);
}
