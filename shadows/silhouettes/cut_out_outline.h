// The silhouette of a cut-out (an alpha-tested card, docs/cut-outs.md): the outline of the
// opaque part of its alpha texture, mapped onto its triangles in world space. A planar card's
// outline is its silhouette from every point of a light that does not lie in its plane, so
// fins, smoothies and penumbra maps can hang their fins on it as on a mesh's silhouette edges
// (Cai et al. 2006, section 3.1: "silhouette edges are those edges which belong to two faces,
// one facing towards the light, and the other facing away"; here, an opaque and a hole).
//
// Exactly: the alpha test reads the nearest texel of the wrapped coordinate
// (raster/nearest_texel.inl), so the opaque part of a texture, in texel space (x, y) =
// (u W, v H), is a union of unit squares, texel column i and row H - 1 - j covering
// [i, i + 1] x [j, j + 1]. Its outline runs along the texel lattice:
//
//   1. per texture, once (textureOutline): the lattice edges between an opaque texel and a
//      hole, walked with the opaque side on the left (x right, y up), straight runs merged
//      into one edge. A clamped axis has holes beyond the texture; a repeated one is periodic
//      with period W, a mirrored one with period 2 W (the texture and its mirror image), and
//      its runs stop at the period's ends, so that they tile;
//   2. per cut-out triangle (cutOutOutline): the runs of every period the triangle's texel
//      coordinates overlap, clipped to the triangle; and the parts of its edges where the
//      texel inside is opaque, unless a neighbour continues the texture across the edge (a
//      card's diagonal: the same texel coordinates at both ends, the same texture, the same
//      sign towards the light). Interior points go to world space by the triangle's affine
//      map, points on an edge by their fraction along it, computed once per edge so that
//      both triangles of an edge share them;
//   3. oriented as fin_geometry.h expects: opaque on the left as the light sees it. A card is
//      an open mesh (silhouette.h, casterSigns): every triangle casts, turned to face the
//      light; the runs are turned again where the texel coordinates mirror the triangle.
//
// Refused: a clamped axis beyond [0, 1] (the edge texel stretched over the rest of the card),
// texture coordinates that are not finite, and more than about a million runs to clip for
// one instance (a texture repeated thousands of times). Such an instance keeps no outline,
// casts the hard shadow of its holes, and is counted (`refusedInstances`).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/edge_adjacency.h"
#include "scenes/scene.h"
#include "shadows/silhouettes/silhouette.h"

namespace shadowlab {

// One straight run of a texture's outline, lattice corner to lattice corner, opaque on its left.
struct TexelRun {
    glm::ivec2 from, to;
};

struct TextureOutline {
    glm::ivec2 period{0};   // texel-space size of the tile that repeats (clamped axes: the texture's)
    glm::bvec2 periodic{false};
    std::vector<TexelRun> runs;
};

// Step 1. Texels at or above the cutoff are opaque, as in the alpha test.
TextureOutline textureOutline(const WorldGeometry::CutOut& texture);

struct CutOutOutline {
    std::vector<glm::vec3> positions;       // world space, the outline's own vertices
    std::vector<uint32_t> vertexInstance;   // per position: its instance, index into Scene::instances
    std::vector<SilhouetteEdge> edges;      // indices into positions, opaque on the left as the light sees it
    size_t refusedInstances = 0;            // no outline (above)
};

// Steps 1 to 3 for every cut-out instance of the scene (world = flatten(scene), adjacency
// from sceneEdgeAdjacency), w.r.t. the light (a point, or a direction with w = 0).
CutOutOutline cutOutOutline(const Scene& scene, const WorldGeometry& world, const std::vector<EdgeAdjacency>& adjacency,
                            const glm::dvec4& light);

}  // namespace shadowlab
