#include "shadows/wedges/wedge_construction.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

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

// A triangle's direction from a finite first vertex a to vertex v: v - a, or v's own
// direction at infinity.
glm::dvec3 from(const glm::vec3& a, const glm::vec4& v) {
    return v.w != 0.0f ? glm::dvec3(v) - glm::dvec3(a) : glm::dvec3(v);
}

// Wound so that its front side faces out of the wedge (inward plane normal m), as the
// rasterizer's culling reads it; `t.x` must be finite.
glm::uvec3 outward(glm::uvec3 t, const std::vector<glm::vec4>& v, const glm::dvec3& m) {
    const glm::vec3 a(v[t.x]);
    const glm::dvec3 n = glm::cross(from(a, v[t.y]), from(a, v[t.z]));
    return glm::dot(n, m) < 0.0 ? t : glm::uvec3(t.x, t.z, t.y);
}

// The cap at infinity, seen from any finite point from inside: wound to be a back face,
// det(g1, g2, g3) > 0 (front facing is det < 0 for three directions).
glm::uvec3 outwardCap(glm::uvec3 t, const std::vector<glm::vec4>& v) {
    const glm::dvec3 g1(v[t.x]), g2(v[t.y]), g3(v[t.z]);
    return glm::dot(glm::cross(g1, g2), g3) > 0.0 ? t : glm::uvec3(t.x, t.z, t.y);
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
    const glm::dvec3 m[4] = {glm::dvec3(front), glm::dvec3(back), glm::dvec3(side0), glm::dvec3(side1)};
    const std::pair<glm::uvec3, int> faces[kWedgeTriangles] = {{{0, 1, 4}, 0}, {{0, 4, 2}, 0}, {{0, 3, 5}, 1},
                                                               {{0, 5, 1}, 1}, {{0, 2, 3}, 2}, {{1, 5, 4}, 3},
                                                               {{2, 4, 5}, -1}, {{2, 5, 3}, -1}};
    for (const auto& [f, plane] : faces) {
        const glm::uvec3 t = f + base;
        set.triangles.push_back(plane < 0 ? outwardCap(t, set.vertices) : outward(t, set.vertices, m[plane]));
    }
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
