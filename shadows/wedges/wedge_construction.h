// Penumbra wedges (Akenine-Möller and Assarsson 2002; Assarsson and Akenine-Möller 2003,
// "A Geometry-based Soft Shadow Volume Algorithm using Graphics Hardware", the wedge
// construction): one per silhouette edge of the light's centre, a convex region that
// holds every point from which the edge, seen towards the light, overlaps the light. Only
// there can the edge change the visible fraction (edge_coverage.h); the wedges are drawn
// so that the per-pixel work runs only where it may matter (wedge_rasterization.h).
//
// The region of edge e0 -> e1 is {e + t (e - l): e on the edge, l on the light, t >= 0},
// which is convex. It is bounded with the light's bounding ball (centre c, radius rho), so
// one construction serves disks and rectangles (the wedge is then conservative, a little
// wider than the paper's, which costs fragments, never correctness):
//   front and back planes: the two planes through the edge's line tangent to the ball;
//   side plane at an end point p: through p, tangent to the ball, tilted from the plane of
//     p and c towards the edge (normal alpha u + sqrt(1 - alpha^2) t_perp, with u the unit
//     vector c -> p, alpha = rho / |p - c|, t_perp the edge direction without its u part),
//     which leaves the ball behind it and the other end point in front.
// The wedges are independent (the 2003 paper's fix of the 2002 one, whose neighbouring
// wedges shared side planes). Each is drawn as 8 triangles over the end points and four
// directions at infinity (w = 0, like the shadow volume's far ends): front and back quads,
// two side triangles and the cap at infinity, wound with their front sides facing out.
//
// An edge whose line meets the ball (an occluder touching the light's bounding sphere) has
// no such planes: it gets no wedge and is evaluated at every pixel instead.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "shading/light_sampling.h"
#include "shadows/silhouettes/silhouette.h"

namespace shadowlab {

// The smallest ball around the light's centre that holds the light.
struct LightBall {
    glm::dvec3 centre{0.0};
    double radius = 0.0;
};
LightBall lightBall(const AreaLightFrame& frame);

constexpr uint32_t kWedgeTriangles = 8;

struct Wedge {
    uint32_t edge = 0;                   // index into the silhouette
    std::array<glm::dvec4, 4> planes;    // front, back, side at `from`, side at `to`: inside where
                                         // dot(xyz, x) + w >= 0
    bool contains(const glm::dvec3& x) const {
        for (const glm::dvec4& p : planes) {
            if (glm::dot(glm::dvec3(p), x) + p.w < 0.0) return false;
        }
        return true;
    }
};

struct WedgeSet {
    std::vector<Wedge> wedges;                 // in silhouette order; wedge k draws triangles 8k..8k+7
    std::vector<uint32_t> unboundedEdges;      // silhouette edges without a wedge, in order
    std::vector<glm::vec4> vertices;           // 6 per wedge: the end points (w = 1), 4 directions (w = 0)
    std::vector<glm::uvec3> triangles;
};

// Zero-length edges cover nothing and get neither a wedge nor a place in unboundedEdges.
WedgeSet buildWedges(std::span<const glm::vec3> positions, std::span<const SilhouetteEdge> silhouette,
                     const LightBall& ball);

}  // namespace shadowlab
