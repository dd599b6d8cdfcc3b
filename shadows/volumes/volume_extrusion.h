// Shadow-volume geometry for the stencil pass, extruded to infinity in homogeneous
// coordinates (Everitt and Kilgard 2002): a vertex p of an occluder stays (p, 1); its
// copy at infinity is (p - L, 0), the direction away from the light (for a directional
// light, minus the light's direction, the same for every vertex). With the infinite
// projection (infinite_projection.h) these are drawn without a far plane.
//
// Every face is wound so that its front side faces out of the volume:
//   side of a silhouette edge a -> b:  (b, a, a_inf) and (b, a_inf, b_inf)
//   light cap: the casting triangle as it is (or reversed, silhouette.h, casterSigns)
//   dark cap:  a triangle projected to infinity, facing away from the light.
// On a closed mesh the light cap is the light-facing triangles and the dark cap the
// back-facing ones projected to infinity (Everitt and Kilgard's z-fail caps); the light
// cap uses the occluder's own vertex positions, so it lands on exactly the depth values
// the occluder has in the camera's depth prepass.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/edge_adjacency.h"
#include "scenes/scene.h"
#include "shadows/silhouettes/silhouette.h"

namespace shadowlab {

struct ShadowVolume {
    std::vector<glm::vec4> vertices;           // world space, w = 1 or w = 0 (at infinity)
    std::vector<glm::uvec3> triangles;         // sides, then light caps, then dark caps
    size_t sideCount = 0, lightCapCount = 0, darkCapCount = 0;
    std::vector<SilhouetteEdge> silhouette;    // world vertex indices, all instances

    std::span<const glm::uvec3> sides() const { return {triangles.data(), sideCount}; }
    std::span<const glm::uvec3> all() const { return triangles; }
};

// One adjacency per scene mesh (indexed like Scene::meshes; empty for unused meshes).
// `withCaps` false builds the sides only (z-pass needs no caps). A volume is extruded from
// whole triangles and cannot follow a cut-out's alpha texture: `cutOutCasts`, one entry per
// WorldGeometry::cutOuts, says whether the instances of that cut-out cast the volume of
// their whole triangles (1) or none (0); empty: every cut-out casts.
ShadowVolume extrudeShadowVolume(const Scene& scene, const WorldGeometry& world,
                                 const std::vector<EdgeAdjacency>& adjacency, const glm::dvec4& light,
                                 bool withCaps, const std::vector<uint8_t>& cutOutCasts = {});

}  // namespace shadowlab
