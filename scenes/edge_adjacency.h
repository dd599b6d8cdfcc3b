// Edge adjacency of a triangle mesh, built once per mesh and shared by its instances:
// which triangles use each edge, and in which direction. It is what silhouette extraction
// (silhouette.h) reads every frame.
//
// Welding. Vertices with equal positions are merged first (a box has 24 vertices, one
// quad's worth per face, but 8 corners), so an edge is found whenever two triangles share
// its end points, whatever their indices. Welding compares object-space positions for
// equality; equal object-space positions become equal world-space positions (the same
// float operations on the same bits), so the weld holds in every instance.
//
// Non-manifold and open edges. An edge may be used by any number of triangles. Each use
// records its direction: +1 if the triangle runs along it from v0 to v1, -1 if from v1 to
// v0. Silhouette extraction needs nothing else: it counts each edge with multiplicity
// (the sum of the directions of its light-facing triangles), which is right for open
// edges (one use), ordinary edges (two uses) and non-manifold ones (three or more) alike.
// A mesh is closed when every edge's directions sum to zero (each edge is walked as often
// one way as the other): then the back-facing triangles close its volume at infinity.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/scene.h"

namespace shadowlab {

struct EdgeUse {
    uint32_t triangle;     // index into the mesh's triangles
    int32_t direction;     // +1: the triangle walks v0 -> v1; -1: v1 -> v0
};

struct MeshEdge {
    uint32_t v0, v1;       // welded vertex indices, v0 < v1
    uint32_t firstUse, useCount;   // range in EdgeAdjacency::uses
};

struct EdgeAdjacency {
    std::vector<uint32_t> weldedVertex;   // per mesh vertex: the smallest index at its position
    std::vector<MeshEdge> edges;          // sorted by (v0, v1)
    std::vector<EdgeUse> uses;            // grouped by edge, in triangle order within an edge
    uint32_t openEdges = 0;               // used by one triangle
    uint32_t nonManifoldEdges = 0;        // used by more than two triangles
    bool closed = true;                   // every edge's directions sum to zero
};

// Triangles whose welded corners coincide have no area and no edges; they are skipped.
EdgeAdjacency buildEdgeAdjacency(std::span<const glm::vec3> positions, std::span<const glm::uvec3> triangles);

// One adjacency per scene mesh that some instance uses (indexed like Scene::meshes, empty
// for unused meshes), built in parallel.
std::vector<EdgeAdjacency> sceneEdgeAdjacency(const Scene& scene);

}  // namespace shadowlab
