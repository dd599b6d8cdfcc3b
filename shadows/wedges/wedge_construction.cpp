#include "shadows/wedges/wedge_construction.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace shadowlab {
namespace {

// A plane through `point` with unit normal n, inside on the side n points to.
glm::dvec4 planeThrough(const glm::dvec3& n, const glm::dvec3& point) { return {n, -glm::dot(n, point)}; }

// Front and back planes: through the edge's line, tangent to the ball, the ball behind
// both. With a the unit vector from the line towards c (perpendicular to it) at distance D
// and b = d x a, the normals cos(phi) a + sin(phi) b with D cos(phi) = -rho.
std::optional<std::array<glm::dvec4, 2>> tangentPlanesThroughEdge(const glm::dvec3& e0, const glm::dvec3& d,
                                                                  const LightBall& ball) {
    const glm::dvec3 q = ball.centre - e0;
    const glm::dvec3 toCentre = q - d * glm::dot(d, q);
    const double distance = glm::length(toCentre);
    if (!(distance > ball.radius)) return std::nullopt;
    const glm::dvec3 a = toCentre / distance, b = glm::cross(d, a);
    const double cosPhi = -ball.radius / distance, sinPhi = std::sqrt(1.0 - cosPhi * cosPhi);
    return std::array<glm::dvec4, 2>{planeThrough(cosPhi * a + sinPhi * b, e0),
                                     planeThrough(cosPhi * a - sinPhi * b, e0)};
}

// Side plane at end point p whose edge continues along unit t: tangent to the ball, the
// ball behind it and the edge in front (dot(normal, t) >= 0).
std::optional<glm::dvec4> sidePlane(const glm::dvec3& p, const glm::dvec3& t, const LightBall& ball) {
    const glm::dvec3 u = glm::normalize(p - ball.centre);
    const glm::dvec3 across = t - u * glm::dot(u, t);
    const double acrossLength = glm::length(across);
    if (!(acrossLength > 1e-9)) return std::nullopt;
    const double alpha = ball.radius / glm::length(p - ball.centre);
    const glm::dvec3 n = alpha * u + std::sqrt(1.0 - alpha * alpha) * (across / acrossLength);
    if (!(glm::dot(n, t) >= 0.0)) return std::nullopt;
    return planeThrough(n, p);
}

// The direction of the line where planes p and q meet, pointing into `inside`'s half-space.
glm::vec4 directionAtInfinity(const glm::dvec4& p, const glm::dvec4& q, const glm::dvec4& inside) {
    glm::dvec3 g = glm::cross(glm::dvec3(p), glm::dvec3(q));
    if (glm::dot(g, glm::dvec3(inside)) < 0.0) g = -g;
    return glm::vec4(glm::vec3(glm::normalize(g)), 0.0f);
}

std::optional<Wedge> wedgeOf(uint32_t edge, const glm::dvec3& e0, const glm::dvec3& e1, const LightBall& ball) {
    const glm::dvec3 d = glm::normalize(e1 - e0);
    const auto frontBack = tangentPlanesThroughEdge(e0, d, ball);
    if (!frontBack) return std::nullopt;
    const auto side0 = sidePlane(e0, d, ball), side1 = sidePlane(e1, -d, ball);
    if (!side0 || !side1) return std::nullopt;
    return Wedge{edge, {(*frontBack)[0], (*frontBack)[1], *side0, *side1}};
}

// Vertices e0, e1, F0, B0, F1, B1 (F, B: front or back plane meeting side plane 0 or 1).
void appendWedgeGeometry(const Wedge& w, const glm::vec3& e0, const glm::vec3& e1, WedgeSet& set) {
    const auto& [front, back, side0, side1] = w.planes;
    const uint32_t base = uint32_t(set.vertices.size());
    set.vertices.insert(set.vertices.end(), {glm::vec4(e0, 1.0f), glm::vec4(e1, 1.0f),
                                             directionAtInfinity(front, side0, back),
                                             directionAtInfinity(back, side0, front),
                                             directionAtInfinity(front, side1, back),
                                             directionAtInfinity(back, side1, front)});
    // front (e0 e1 F1 F0), back (e0 B0 B1 e1), sides (e0 F0 B0), (e1 B1 F1), cap (F0 F1 B1 B0)
    static constexpr glm::uvec3 kFaces[kWedgeTriangles] = {{0, 1, 4}, {0, 4, 2}, {0, 3, 5}, {0, 5, 1},
                                                           {0, 2, 3}, {1, 5, 4}, {2, 4, 5}, {2, 5, 3}};
    for (const glm::uvec3& f : kFaces) set.triangles.push_back(f + base);
}

}  // namespace

LightBall lightBall(const AreaLightFrame& frame) {
    const double radius = frame.disk ? glm::length(frame.axisA)
                                     : std::max(glm::length(frame.axisA + frame.axisB),
                                                glm::length(frame.axisA - frame.axisB));
    return {frame.centre, radius};
}

WedgeSet buildWedges(std::span<const glm::vec3> positions, std::span<const SilhouetteEdge> silhouette,
                     const LightBall& ball) {
    WedgeSet set;
    for (uint32_t k = 0; k < silhouette.size(); ++k) {
        const glm::vec3 e0 = positions[silhouette[k].from], e1 = positions[silhouette[k].to];
        if (e0 == e1) continue;
        const std::optional<Wedge> w = wedgeOf(k, glm::dvec3(e0), glm::dvec3(e1), ball);
        if (!w) {
            set.unboundedEdges.push_back(k);
            continue;
        }
        set.wedges.push_back(*w);
        appendWedgeGeometry(*w, e0, e1, set);
    }
    return set;
}

}  // namespace shadowlab
