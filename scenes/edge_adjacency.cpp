#include "scenes/edge_adjacency.h"

#include <algorithm>
#include <numeric>
#include <tuple>

#include <tbb/parallel_for.h>

namespace shadowlab {
namespace {

// Each vertex mapped to the smallest index with an equal position: sort indices by
// position (ties by index), then every run of equal positions takes its first index.
std::vector<uint32_t> weldVertices(std::span<const glm::vec3> positions) {
    std::vector<uint32_t> order(positions.size());
    std::iota(order.begin(), order.end(), 0u);
    auto key = [&](uint32_t i) { return std::tie(positions[i].x, positions[i].y, positions[i].z); };
    std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
        return key(a) < key(b) || (key(a) == key(b) && a < b);
    });
    std::vector<uint32_t> welded(positions.size());
    for (size_t k = 0; k < order.size(); ++k) {
        const bool startsRun = k == 0 || key(order[k - 1]) < key(order[k]);
        welded[order[k]] = startsRun ? order[k] : welded[order[k - 1]];
    }
    return welded;
}

struct EdgeRecord {
    uint32_t v0, v1, triangle;
    int32_t direction;
    auto sortKey() const { return std::tie(v0, v1, triangle); }
};

std::vector<EdgeRecord> edgeRecords(std::span<const glm::uvec3> triangles, const std::vector<uint32_t>& welded) {
    std::vector<EdgeRecord> records;
    records.reserve(triangles.size() * 3);
    for (uint32_t t = 0; t < triangles.size(); ++t) {
        const uint32_t corner[3] = {welded[triangles[t].x], welded[triangles[t].y], welded[triangles[t].z]};
        if (corner[0] == corner[1] || corner[1] == corner[2] || corner[2] == corner[0]) continue;
        for (int k = 0; k < 3; ++k) {
            const uint32_t from = corner[k], to = corner[(k + 1) % 3];
            records.push_back({std::min(from, to), std::max(from, to), t, from < to ? 1 : -1});
        }
    }
    std::sort(records.begin(), records.end(),
              [](const EdgeRecord& a, const EdgeRecord& b) { return a.sortKey() < b.sortKey(); });
    return records;
}

// The meshes some instance uses.
std::vector<bool> usedMeshes(const Scene& scene) {
    std::vector<bool> used(scene.meshes.size(), false);
    for (const MeshInstance& instance : scene.instances) used[instance.mesh] = true;
    return used;
}

}  // namespace

EdgeAdjacency buildEdgeAdjacency(std::span<const glm::vec3> positions, std::span<const glm::uvec3> triangles) {
    EdgeAdjacency adjacency;
    adjacency.weldedVertex = weldVertices(positions);
    const std::vector<EdgeRecord> records = edgeRecords(triangles, adjacency.weldedVertex);
    adjacency.uses.reserve(records.size());
    for (size_t k = 0; k < records.size(); ++k) {
        const EdgeRecord& r = records[k];
        const bool newEdge = k == 0 || r.v0 != records[k - 1].v0 || r.v1 != records[k - 1].v1;
        if (newEdge) adjacency.edges.push_back({r.v0, r.v1, uint32_t(k), 0});
        adjacency.edges.back().useCount++;
        adjacency.uses.push_back({r.triangle, r.direction});
    }
    for (const MeshEdge& e : adjacency.edges) {
        int32_t balance = 0;
        for (uint32_t u = e.firstUse; u < e.firstUse + e.useCount; ++u) balance += adjacency.uses[u].direction;
        adjacency.closed = adjacency.closed && balance == 0;
        adjacency.openEdges += e.useCount == 1;
        adjacency.nonManifoldEdges += e.useCount > 2;
    }
    return adjacency;
}

std::vector<EdgeAdjacency> sceneEdgeAdjacency(const Scene& scene) {
    const std::vector<bool> used = usedMeshes(scene);
    std::vector<EdgeAdjacency> adjacency(scene.meshes.size());
    tbb::parallel_for(size_t(0), scene.meshes.size(), [&](size_t m) {
        if (used[m]) adjacency[m] = buildEdgeAdjacency(scene.meshes[m].positions, scene.meshes[m].triangles);
    });
    return adjacency;
}

}  // namespace shadowlab
