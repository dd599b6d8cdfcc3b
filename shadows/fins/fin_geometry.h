// Shadow fins: planar primitives attached to the silhouette edges of the occluders as the
// centre of a disk light sees them (Cai, Jia, Wang, Hu and Martin 2006, "Rendering Soft
// Shadows using Multi-layered Shadow Fins", section 3.1 and Figure 4). One mechanism builds
// the fins of three techniques:
//
//   fins           (Cai et al.) inner and outer fins, weight s = 0.5 (1 - t) (eq. 1), sized
//                  by the light's radius for the reference receiver plane (eq. 3);
//   penumbra-maps  (Wyman and Hansen 2003) outer fins only, sized by the light's radius,
//                  weight 1 - t: the whole penumbra lies outside the hard shadow;
//   smoothies      (Chan and Durand 2003) outer fins only, weight 1 - t, sized by one
//                  global parameter, an angular width t_s as seen from the light's centre,
//                  so the light's size plays no part (Cai et al., section 7.1).
//
// Construction (section 3.1). L(p) is the distance of p from the light's plane. From each end
// v of a silhouette edge a line is drawn perpendicular to the edge in the plane L = L(v),
// parallel to the light's plane, outwards (away from the occluder as the light's centre
// sees it) for the outer fin and inwards for the inner fin; its length is the fin width B at
// L(v). The two lines and the edge make a quad. Where two silhouette edges meet, a circular
// sector of radius B in the plane L = L(v) fills the gap between their quads: an outer fan
// at a convex corner (the outer quads diverge), an inner fan at a concave one. Where more
// than two silhouette edges meet, Chan and Durand's construction (section 3.1, last
// paragraph): an averaged direction a gives one point v + B a (v - B a for the inner fins),
// joined by a triangle to the end line of each edge's fin. Chan and Durand average the
// adjacent faces' normals and project the result into the light's image; here the edges'
// outward directions are averaged, which already lie in the plane parallel to the light's
// and point away from the occluder. Where a vertex ends a single edge, or two edges walked
// the same way meet (inconsistently oriented open meshes), nothing joins the fins.
// Overlapping fins are not trimmed (section 3.1): the min and max rules of the penumbra maps
// absorb the overlaps.
//
// Every vertex carries its weight s_0: the edge weight on the silhouette, 0 on the fin's
// far side. The light's view interpolates it perspective-correctly, which reproduces the
// linear fall-off of eq. 1 exactly across each triangle.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/scene.h"
#include "shadows/silhouettes/silhouette.h"

namespace shadowlab {

// A disk light's plane: centre, unit normal towards the scene, radius R (m).
struct LightPlane {
    glm::dvec3 centre{0.0}, normal{0.0, -1.0, 0.0};
    double radius = 0.0;
    // L(p): distance from the light's plane, m (L_r, L_b of eq. 3).
    double distance(const glm::dvec3& p) const { return glm::dot(p - centre, normal); }
};
// Throws std::invalid_argument unless the light is a disk.
LightPlane lightPlaneOf(const Light& light);

// How wide a fin is at distance Lb from the light's plane for a receiver plane at Lr.
struct FinSizing {
    enum class Kind { LightRadius, AngularWidth };
    Kind kind = Kind::LightRadius;
    double value = 0.0;   // LightRadius: R (m); AngularWidth: t_s (tangent of the angle)

    // Eq. 3, B = R (Lr - Lb) / Lr: the penumbra's half width on a receiver plane at Lr,
    // projected through the light's centre back to the fin's plane at Lb. Smoothies put
    // t_s Lb in place of R: a width fixed as seen from the light (Chan and Durand 2003).
    double width(double Lb, double Lr) const;
};

struct FinStyle {
    bool innerFins = true;
    float edgeWeight = 0.5f;   // s at the silhouette: 0.5 (eq. 1), or 1 for outer-only methods
    FinSizing sizing;
};

// The inner or the outer fins, as triangles for the rasterizer.
struct FinPrimitives {
    std::vector<glm::vec3> positions;    // world space
    std::vector<float> weights;          // s_0 per vertex
    std::vector<glm::uvec3> triangles;
    std::vector<uint32_t> owner;         // per triangle: its edge, index into Fins::edges
};

struct Fins {
    std::vector<SilhouetteEdge> edges;        // the edges that got fins (duplicates dropped)
    std::vector<double> midpointDistance;     // L of each edge's midpoint (layering, section 4.1)
    FinPrimitives inner, outer;               // inner is empty unless style.innerFins
};

// Fins of `silhouette` (world vertex indices into `positions`), sized for the reference
// receiver plane at L0, the far plane of the light's view (section 3.1). Edges with an end
// at or behind the light's plane, or pointing along its normal (no perpendicular in a plane
// parallel to it), get no fin.
Fins buildFins(std::span<const glm::vec3> positions, std::span<const SilhouetteEdge> silhouette,
               const LightPlane& light, double referenceDistance, const FinStyle& style);

}  // namespace shadowlab
