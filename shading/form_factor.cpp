#include "shading/form_factor.h"

#include <algorithm>
#include <numbers>
#include <vector>

#include "raster/portable_math.h"

namespace shadowlab {
namespace {

// The polygon's unit normal by Newell's method, on its emitting (counter-clockwise) side.
glm::dvec3 polygonNormal(std::span<const glm::dvec3> polygon) {
    glm::dvec3 sum(0.0);
    for (size_t k = 0; k < polygon.size(); ++k) sum += glm::cross(polygon[k], polygon[(k + 1) % polygon.size()]);
    const double length = glm::length(sum);
    return length > 0.0 ? sum / length : glm::dvec3(0.0);
}

// The corners relative to x, clipped to the half-space n . r >= 0 (Sutherland-Hodgman
// against one plane), into `out` (room for 2 polygon.size() corners: each edge adds
// at most its first corner and a crossing); returns how many.
// What lies below the receiver's horizon sends it nothing.
size_t aboveHorizon(const glm::dvec3& x, const glm::dvec3& n, std::span<const glm::dvec3> polygon, glm::dvec3* out) {
    size_t count = 0;
    for (size_t k = 0; k < polygon.size(); ++k) {
        const glm::dvec3 a = polygon[k] - x, b = polygon[(k + 1) % polygon.size()] - x;
        const double ha = glm::dot(n, a), hb = glm::dot(n, b);
        if (ha >= 0.0) out[count++] = a;
        if ((ha >= 0.0) != (hb >= 0.0)) out[count++] = a + (b - a) * (ha / (ha - hb));
    }
    return count;
}

}  // namespace

double pointToPolygonFormFactor(const glm::dvec3& x, const glm::dvec3& n, std::span<const glm::dvec3> polygon) {
    if (polygon.size() < 3) return 0.0;
    // A one-sided emitter: x must be in front of the polygon's plane.
    if (glm::dot(polygonNormal(polygon), x - polygon[0]) <= 0.0) return 0.0;
    // Small polygons (the patches of differential/) clip on the stack.
    constexpr size_t kStackCorners = 8;
    glm::dvec3 stack[2 * kStackCorners];
    std::vector<glm::dvec3> heap(polygon.size() > kStackCorners ? 2 * polygon.size() : 0);
    glm::dvec3* r = heap.empty() ? stack : heap.data();
    const size_t count = aboveHorizon(x, n, polygon, r);
    double sum = 0.0;
    for (size_t k = 0; k < count; ++k) {
        const glm::dvec3& a = r[k];
        const glm::dvec3& b = r[(k + 1) % count];
        const glm::dvec3 c = glm::cross(a, b);
        const double sine = glm::length(c);
        if (sine == 0.0) continue;   // an edge through x or of no length subtends nothing
        sum += portable::atan2(sine, glm::dot(a, b)) * glm::dot(n, c) / sine;
    }
    // Counter-clockwise seen from the emitting side is clockwise seen from x: the sum is
    // negative for a polygon x faces; its magnitude is 2 pi F.
    return std::clamp(-sum / (2.0 * std::numbers::pi), 0.0, 1.0);
}

}  // namespace shadowlab
