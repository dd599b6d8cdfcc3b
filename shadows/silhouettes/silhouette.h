// Silhouette edges of a mesh instance as seen from the light, recomputed every frame from
// the edge adjacency (edge_adjacency.h). Only these edges need shadow-volume sides: an
// edge between two triangles that both face the light (or both face away) bounds no
// shadow (Lehtinen 2015, "Smarter Shadow Volumes"; RTR 4th ed., section 7.3).
//
// Each triangle enters the volume with a sign (casterSigns()):
//   closed mesh (Everitt and Kilgard 2002): light-facing triangles +1 (they are the light
//       cap and their volumes, summed, are the object's shadow), back-facing ones 0;
//   open mesh (Crow 1977, one volume per polygon): every triangle casts, turned to face
//       the light: +1 if it faces it, -1 (reversed) if it faces away. A single-sided quad
//       seen from the wrong side still blocks light, as it does for the reference's rays.
// The multiplicity of an edge is the sum over its uses of direction * sign. Volumes of two
// triangles that walk a shared edge in opposite directions cancel there, so an edge with
// multiplicity 0 needs no side; otherwise |m| sides, walked v0 -> v1 if m > 0. On a closed
// 2-manifold mesh this gives exactly the edges between a light-facing and a back-facing
// triangle; on an open one also the open edges of casting triangles; on non-manifold edges
// the count the union of the triangles' volumes needs (stencil counting adds them).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/edge_adjacency.h"
#include "scenes/scene.h"

namespace shadowlab {

// From p towards the light (not normalised): L - p, or the light's direction.
inline glm::dvec3 towardsLight(const glm::dvec4& light, const glm::dvec3& p) {
    return glm::dvec3(light) - light.w * p;
}

// The same test the reference makes per pixel, dot(N, L - P) > 0 (reference.h), made
// once per triangle in double with N = (b - a) x (c - a) and P = a.
bool facesLight(const glm::dvec4& light, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c);

struct CasterSigns {
    int light;   // +1: light cap as it is; -1: reversed; 0: not a light cap
    int dark;    // the same for the dark cap, projected to infinity
};
CasterSigns casterSigns(bool facesLight, bool closedMesh);

struct InstanceRange;
// casterSigns() of every triangle of one instance (world = flatten(scene)).
std::vector<CasterSigns> instanceCasterSigns(const WorldGeometry& world, const InstanceRange& range,
                                             const glm::dvec4& light, bool closedMesh);
// The `light` member of each, as silhouetteEdges() takes them.
std::vector<int8_t> lightSigns(const std::vector<CasterSigns>& signs);

// An edge that needs a volume side, in world vertex indices, walked from -> to as its
// casting triangles walk it; emitted |multiplicity| times.
struct SilhouetteEdge {
    uint32_t from, to;
};

// `lightSign` per mesh triangle (CasterSigns::light); `vertexBase` maps welded mesh vertex
// indices to world ones. Edges come out in the adjacency's edge order.
std::vector<SilhouetteEdge> silhouetteEdges(const EdgeAdjacency& adjacency, std::span<const int8_t> lightSign,
                                            uint32_t vertexBase);

// The silhouette edges of every instance of the scene (world = flatten(scene), adjacency
// from sceneEdgeAdjacency), instance by instance: the light signs above per triangle, then
// silhouetteEdges. Throws std::invalid_argument if world is not flatten(scene).
std::vector<SilhouetteEdge> sceneSilhouette(const Scene& scene, const WorldGeometry& world,
                                            const std::vector<EdgeAdjacency>& adjacency, const glm::dvec4& light);

}  // namespace shadowlab
