#include "shadows/wedges/edge_coverage.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <utility>

#include "raster/portable_math.h"

namespace shadowlab {
namespace {

constexpr double kHorizon = 1e-6;   // the edge is cut this share of P's distance before P's level

double cross2(const glm::dvec2& a, const glm::dvec2& b) { return a.x * b.y - a.y * b.x; }

struct ProjectedEdge {
    glm::dvec2 a, b;   // light coordinates, the centre at the origin
    double side;       // +1 if P is on the normal's side of the light's plane, else -1
};

// The edge cut to the points between P's level and the light, projected from P.
std::optional<ProjectedEdge> projectEdge(const AreaLightPlane& light, const glm::dvec3& p, glm::dvec3 x0,
                                        glm::dvec3 x1) {
    const double signedHeight = glm::dot(light.normal, p - light.centre);
    const double side = signedHeight >= 0.0 ? 1.0 : -1.0, height = std::abs(signedHeight);
    const double limit = height * (1.0 - kHorizon);
    const double h0 = side * glm::dot(light.normal, x0 - light.centre);
    const double h1 = side * glm::dot(light.normal, x1 - light.centre);
    if (!(height > 0.0) || (h0 >= limit && h1 >= limit)) return std::nullopt;
    if (h0 > limit) x0 = x1 + (x0 - x1) * ((limit - h1) / (h0 - h1));
    if (h1 > limit) x1 = x0 + (x1 - x0) * ((limit - h0) / (h1 - h0));
    const auto project = [&](const glm::dvec3& x, double h) {
        const glm::dvec3 y = p + (x - p) * (height / (height - h)) - light.centre;
        return glm::dvec2(glm::dot(y, light.dualA), glm::dot(y, light.dualB));
    };
    return ProjectedEdge{project(x0, side * glm::dot(light.normal, x0 - light.centre)),
                         project(x1, side * glm::dot(light.normal, x1 - light.centre)), side};
}

// dot(n, x) >= offset, n of unit length.
struct HalfPlane {
    glm::dvec2 n;
    double offset;
};

// R_e of a -> b for sigma = sign(cross(a, b)): the b side of ray a, the a side of ray b,
// and across the line a b from the origin.
std::array<HalfPlane, 3> beyondEdge(const glm::dvec2& a, const glm::dvec2& b, double sigma) {
    const glm::dvec2 e = b - a;
    const glm::dvec2 acrossLine = -sigma * glm::dvec2(-e.y, e.x) / glm::length(e);
    return {HalfPlane{sigma * glm::dvec2(-a.y, a.x) / glm::length(a), 0.0},
            HalfPlane{sigma * glm::dvec2(b.y, -b.x) / glm::length(b), 0.0},
            HalfPlane{acrossLine, glm::dot(acrossLine, a)}};
}

// Area of [-1, 1]^2 n the half-planes (Sutherland-Hodgman; at most 4 + 3 vertices).
double squareClippedArea(const std::array<HalfPlane, 3>& planes) {
    std::array<glm::dvec2, 8> poly = {glm::dvec2(-1, -1), glm::dvec2(1, -1), glm::dvec2(1, 1), glm::dvec2(-1, 1)};
    size_t count = 4;
    for (const HalfPlane& h : planes) {
        std::array<glm::dvec2, 8> out;
        size_t kept = 0;
        for (size_t i = 0; i < count; ++i) {
            const glm::dvec2 &s = poly[i], &t = poly[(i + 1) % count];
            const double ds = glm::dot(h.n, s) - h.offset, dt = glm::dot(h.n, t) - h.offset;
            if (ds >= 0.0) out[kept++] = s;
            if ((ds >= 0.0) != (dt >= 0.0)) out[kept++] = s + (t - s) * (ds / (ds - dt));
        }
        poly = out, count = kept;
    }
    double twice = 0.0;
    for (size_t i = 0; i < count; ++i) twice += cross2(poly[i], poly[(i + 1) % count]);
    return 0.5 * twice;
}

// area(D n R_e) for the unit disk: the piece [p, q] of a -> b inside the circle, found from
// the foot of the origin on the line (well conditioned however far out a and b are).
double diskBeyondArea(const glm::dvec2& a, const glm::dvec2& b) {
    const glm::dvec2 e = b - a;
    const double ee = glm::dot(e, e);
    const double tFoot = -glm::dot(a, e) / ee;
    const glm::dvec2 foot = a + tFoot * e;
    const double halfChord2 = 1.0 - glm::dot(foot, foot);
    if (!(halfChord2 > 0.0)) return 0.0;
    const double halfChord = std::sqrt(halfChord2 / ee);
    const double t0 = std::max(0.0, tFoot - halfChord), t1 = std::min(1.0, tFoot + halfChord);
    if (!(t1 > t0)) return 0.0;
    const glm::dvec2 p = a + t0 * e, q = a + t1 * e;
    const double crossPQ = std::abs(cross2(p, q));
    return 0.5 * (portable::atan2(crossPQ, glm::dot(p, q)) - crossPQ);
}

// Where the origin lies against the segment a b: within kNearCentre of it, and whether its
// foot on the line falls between a and b.
std::pair<bool, bool> nearSegment(const glm::dvec2& a, const glm::dvec2& b) {
    const glm::dvec2 e = b - a;
    const double length = glm::length(e);
    const double along = -glm::dot(a, e) / length;
    const double outside = std::max({0.0, -along, along - length});
    const double distance = portable::hypot(cross2(a, e) / length, outside);
    return {distance < kNearCentre, along >= 0.0 && along <= length};
}

}  // namespace

EdgeCoverage edgeCoverage(const AreaLightPlane& light, const glm::dvec3& p, const glm::dvec3& x0,
                          const glm::dvec3& x1) {
    const std::optional<ProjectedEdge> e = projectEdge(light, p, x0, x1);
    if (!e) return {};
    const double c = cross2(e->a, e->b);
    if (!(c != 0.0)) return {};   // the centre on the edge's line: a degenerate cone, no area
    const double sigma = c > 0.0 ? 1.0 : -1.0;
    const double share = light.disk ? diskBeyondArea(e->a, e->b) / std::numbers::pi
                                    : squareClippedArea(beyondEdge(e->a, e->b, sigma)) / 4.0;
    const auto [nearCentre, inSpan] = nearSegment(e->a, e->b);
    return {e->side * sigma * share, nearCentre, inSpan, e->side * sigma};
}

}  // namespace shadowlab
