#include "shadows/fins/fin_geometry.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "raster/portable_math.h"

namespace shadowlab {
namespace {

// Fans are cut into sectors of at most this angle: a chord then stays within
// 1 - cos(step / 2) = 0.5% of the radius from the arc.
constexpr double kFanStepRadians = std::numbers::pi / 16.0;
// Quads whose end lines differ by less than this angle already meet: no fan between them.
constexpr double kMinFanRadians = 1e-3;
// An edge whose direction has less than this fraction of its length across the light's
// normal points (almost) at the light's plane: its perpendicular in a plane parallel to the
// light's is undefined, and its shadow as the centre sees it is (almost) a point.
constexpr double kMinAcrossNormal = 1e-6;
// Averaged directions shorter than this (opposite edges cancelling) give no corner point.
constexpr double kMinAverageLength = 1e-6;

// One silhouette edge a -> b with what its fins need.
struct EdgeFrame {
    glm::dvec3 a, b;
    glm::dvec3 along;      // unit, a -> b
    glm::dvec3 outward;    // unit, perpendicular to the edge and to the light's normal
    double widthA, widthB; // fin width B at each end (eq. 3 for the reference plane)
};

// The outward side is the side of the plane through the edge and the light's centre that
// the occluder is not on. The light-facing triangle walks its silhouette edge a -> b
// counter-clockwise (silhouette.h), so the normal (b - a) x (c - a) of that plane points
// away from it; the fin direction n x (b - a) is turned to agree with it.
bool edgeFrame(const glm::dvec3& a, const glm::dvec3& b, const LightPlane& light, double L0, const FinSizing& sizing,
               EdgeFrame& f) {
    const double La = light.distance(a), Lb = light.distance(b);
    if (!(La > 0.0) || !(Lb > 0.0)) return false;
    const glm::dvec3 edge = b - a;
    const glm::dvec3 across = glm::cross(light.normal, edge);
    if (!(glm::length(across) > kMinAcrossNormal * glm::length(edge))) return false;
    f.a = a, f.b = b;
    f.along = glm::normalize(edge);
    f.outward = glm::normalize(across);
    if (glm::dot(f.outward, glm::cross(edge, light.centre - a)) < 0.0) f.outward = -f.outward;
    f.widthA = std::max(0.0, sizing.width(La, L0));
    f.widthB = std::max(0.0, sizing.width(Lb, L0));
    return true;
}

class FinBuilder {
public:
    FinBuilder(FinPrimitives& out, float edgeWeight) : out_(out), edgeWeight_(edgeWeight) {}

    // The quad a, a + B_a d, b + B_b d, b: weight s_0 on the edge, 0 on the far side.
    void quad(const EdgeFrame& f, const glm::dvec3& d, uint32_t owner) {
        const uint32_t a = vertex(f.a, edgeWeight_), aFar = vertex(f.a + f.widthA * d, 0.0f);
        const uint32_t bFar = vertex(f.b + f.widthB * d, 0.0f), b = vertex(f.b, edgeWeight_);
        triangle({a, aFar, bFar}, owner);
        triangle({a, bFar, b}, owner);
    }

    // The circular sector of radius `width` around v from direction `from` to `to` (unit,
    // both perpendicular to the light's normal), through the smaller angle.
    void fan(const glm::dvec3& v, const glm::dvec3& from, const glm::dvec3& to, double width, uint32_t owner) {
        const double angle = portable::acos(std::clamp(glm::dot(from, to), -1.0, 1.0));
        if (angle < kMinFanRadians || !(width > 0.0)) return;
        const glm::dvec3 towards = glm::normalize(to - glm::dot(to, from) * from);
        const int steps = int(std::ceil(angle / kFanStepRadians));
        const uint32_t centre = vertex(v, edgeWeight_);
        uint32_t previous = vertex(v + width * from, 0.0f);
        for (int k = 1; k <= steps; ++k) {
            const double phi = angle * k / steps;
            const uint32_t next = vertex(v + width * (portable::cos(phi) * from + portable::sin(phi) * towards), 0.0f);
            triangle({centre, previous, next}, owner);
            previous = next;
        }
    }

    // Chan and Durand's corner piece: v, the far end of one edge's fin line, the corner point.
    void cornerTriangle(const glm::dvec3& v, const glm::dvec3& edgeEnd, const glm::dvec3& corner, uint32_t owner) {
        triangle({vertex(v, edgeWeight_), vertex(edgeEnd, 0.0f), vertex(corner, 0.0f)}, owner);
    }

private:
    uint32_t vertex(const glm::dvec3& p, float weight) {
        out_.positions.push_back(glm::vec3(p));
        out_.weights.push_back(weight);
        return uint32_t(out_.positions.size() - 1);
    }
    void triangle(const glm::uvec3& t, uint32_t owner) {
        out_.triangles.push_back(t);
        out_.owner.push_back(owner);
    }
    FinPrimitives& out_;
    float edgeWeight_;
};

// An edge's end at a silhouette vertex: the edge arrives there (its `to`) or leaves.
struct EdgeEnd {
    uint32_t vertex, edge;
    bool leaves;
};

std::vector<EdgeEnd> edgeEndsByVertex(std::span<const SilhouetteEdge> edges) {
    std::vector<EdgeEnd> ends;
    for (uint32_t e = 0; e < edges.size(); ++e) {
        ends.push_back({edges[e].from, e, true});
        ends.push_back({edges[e].to, e, false});
    }
    std::sort(ends.begin(), ends.end(), [](const EdgeEnd& x, const EdgeEnd& y) {
        return x.vertex != y.vertex ? x.vertex < y.vertex : x.edge < y.edge;
    });
    return ends;
}

// Where exactly two edges meet, one arriving (e1) and one leaving (e2): the corner is convex
// as the light sees it when the second edge's outward direction points forward along the
// first edge; then the outer quads diverge and an outer fan joins them, otherwise the inner
// quads do and an inner fan joins those. The fan belongs to the arriving edge.
void joinTwo(const std::vector<EdgeFrame>& frames, const EdgeEnd& x, const EdgeEnd& y, const FinStyle& style,
             FinBuilder& inner, FinBuilder& outer) {
    if (x.leaves == y.leaves) return;   // inconsistently walked edges: nothing to join
    const EdgeFrame& arriving = frames[x.leaves ? y.edge : x.edge];
    const EdgeFrame& leaving = frames[x.leaves ? x.edge : y.edge];
    const uint32_t owner = x.leaves ? y.edge : x.edge;
    const glm::dvec3& v = leaving.a;
    const double width = leaving.widthA;
    if (glm::dot(leaving.outward, arriving.along) > 0.0) {
        outer.fan(v, arriving.outward, leaving.outward, width, owner);
    } else if (style.innerFins) {
        inner.fan(v, -arriving.outward, -leaving.outward, width, owner);
    }
}

// More than two edges at one vertex (section 3.1, after Chan and Durand 2003).
void joinMany(const std::vector<EdgeFrame>& frames, std::span<const EdgeEnd> ends, const FinStyle& style,
              FinBuilder& inner, FinBuilder& outer) {
    glm::dvec3 sum(0.0);
    for (const EdgeEnd& end : ends) sum += frames[end.edge].outward;
    if (!(glm::length(sum) > kMinAverageLength)) return;
    const glm::dvec3 average = glm::normalize(sum);
    for (const EdgeEnd& end : ends) {
        const EdgeFrame& f = frames[end.edge];
        const glm::dvec3& v = end.leaves ? f.a : f.b;
        const double width = end.leaves ? f.widthA : f.widthB;
        outer.cornerTriangle(v, v + width * f.outward, v + width * average, end.edge);
        if (style.innerFins) inner.cornerTriangle(v, v - width * f.outward, v - width * average, end.edge);
    }
}

}  // namespace

LightPlane lightPlaneOf(const Light& light) {
    if (light.type != LightType::Disk) throw std::invalid_argument("shadow fins need a disk light");
    return {glm::dvec3(light.position), glm::normalize(glm::dvec3(light.direction)), double(light.radius)};
}

double FinSizing::width(double Lb, double Lr) const {
    const double radius = kind == Kind::LightRadius ? value : value * Lb;
    return radius * (Lr - Lb) / Lr;
}

Fins buildFins(std::span<const glm::vec3> positions, std::span<const SilhouetteEdge> silhouette,
               const LightPlane& light, double referenceDistance, const FinStyle& style) {
    Fins fins;
    std::vector<EdgeFrame> frames;
    for (size_t k = 0; k < silhouette.size(); ++k) {
        const SilhouetteEdge& e = silhouette[k];
        // An edge of multiplicity m comes m times in a row (silhouette.h); it needs one fin.
        if (k > 0 && e.from == silhouette[k - 1].from && e.to == silhouette[k - 1].to) continue;
        EdgeFrame f;
        if (!edgeFrame(glm::dvec3(positions[e.from]), glm::dvec3(positions[e.to]), light, referenceDistance,
                       style.sizing, f)) {
            continue;
        }
        fins.edges.push_back(e);
        fins.midpointDistance.push_back(light.distance(0.5 * (f.a + f.b)));
        frames.push_back(f);
    }
    FinBuilder inner(fins.inner, style.edgeWeight), outer(fins.outer, style.edgeWeight);
    for (uint32_t e = 0; e < frames.size(); ++e) {
        outer.quad(frames[e], frames[e].outward, e);
        if (style.innerFins) inner.quad(frames[e], -frames[e].outward, e);
    }
    const std::vector<EdgeEnd> ends = edgeEndsByVertex(fins.edges);
    for (size_t first = 0; first < ends.size();) {
        size_t last = first;
        while (last < ends.size() && ends[last].vertex == ends[first].vertex) ++last;
        const std::span<const EdgeEnd> atVertex(ends.data() + first, last - first);
        if (atVertex.size() == 2) joinTwo(frames, atVertex[0], atVertex[1], style, inner, outer);
        if (atVertex.size() > 2) joinMany(frames, atVertex, style, inner, outer);
        first = last;
    }
    return fins;
}

}  // namespace shadowlab
