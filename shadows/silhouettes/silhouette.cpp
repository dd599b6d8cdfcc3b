#include "shadows/silhouettes/silhouette.h"

#include <cstdlib>
#include <stdexcept>

#include <tbb/parallel_for.h>

namespace shadowlab {

bool facesLight(const glm::dvec4& light, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const glm::dvec3 A(a), B(b), C(c);
    return glm::dot(glm::cross(B - A, C - A), towardsLight(light, A)) > 0.0;
}

CasterSigns casterSigns(bool lit, bool closedMesh) {
    if (closedMesh) return lit ? CasterSigns{+1, 0} : CasterSigns{0, +1};
    return lit ? CasterSigns{+1, -1} : CasterSigns{-1, +1};
}

std::vector<int8_t> lightSigns(const std::vector<CasterSigns>& signs) {
    std::vector<int8_t> light;
    for (const CasterSigns& s : signs) light.push_back(int8_t(s.light));
    return light;
}

std::vector<CasterSigns> instanceCasterSigns(const WorldGeometry& world, const InstanceRange& range,
                                             const glm::dvec4& light, bool closedMesh) {
    std::vector<CasterSigns> signs(range.triangleCount);
    for (uint32_t t = 0; t < range.triangleCount; ++t) {
        const glm::uvec3& tri = world.triangles[range.firstTriangle + t];
        const bool lit = facesLight(light, world.positions[tri.x], world.positions[tri.y], world.positions[tri.z]);
        signs[t] = casterSigns(lit, closedMesh);
    }
    return signs;
}

std::vector<SilhouetteEdge> silhouetteEdges(const EdgeAdjacency& adjacency, std::span<const int8_t> lightSign,
                                            uint32_t vertexBase) {
    std::vector<SilhouetteEdge> silhouette;
    for (const MeshEdge& e : adjacency.edges) {
        int multiplicity = 0;
        for (uint32_t u = e.firstUse; u < e.firstUse + e.useCount; ++u) {
            multiplicity += adjacency.uses[u].direction * lightSign[adjacency.uses[u].triangle];
        }
        const SilhouetteEdge edge = multiplicity > 0 ? SilhouetteEdge{vertexBase + e.v0, vertexBase + e.v1}
                                                     : SilhouetteEdge{vertexBase + e.v1, vertexBase + e.v0};
        for (int k = 0; k < std::abs(multiplicity); ++k) silhouette.push_back(edge);
    }
    return silhouette;
}

std::vector<SilhouetteEdge> sceneSilhouette(const Scene& scene, const WorldGeometry& world,
                                            const std::vector<EdgeAdjacency>& adjacency, const glm::dvec4& light) {
    const std::vector<InstanceRange> ranges = instanceRanges(scene);
    if (!ranges.empty() && ranges.back().firstTriangle + ranges.back().triangleCount != world.triangles.size()) {
        throw std::invalid_argument("sceneSilhouette: world geometry is not flatten(scene)");
    }
    std::vector<std::vector<SilhouetteEdge>> parts(ranges.size());
    tbb::parallel_for(size_t(0), ranges.size(), [&](size_t i) {
        const InstanceRange& r = ranges[i];
        const EdgeAdjacency& a = adjacency[r.mesh];
        parts[i] = silhouetteEdges(a, lightSigns(instanceCasterSigns(world, r, light, a.closed)), r.firstVertex);
    });
    std::vector<SilhouetteEdge> all;   // in instance order, whatever the threads did
    for (const std::vector<SilhouetteEdge>& part : parts) all.insert(all.end(), part.begin(), part.end());
    return all;
}

}  // namespace shadowlab
