#include "shadows/silhouette.h"

#include <cstdlib>

namespace shadowlab {

glm::dvec4 homogeneousLight(const Light& light) {
    if (light.type == LightType::Directional) return glm::dvec4(glm::dvec3(light.direction), 0.0);
    return glm::dvec4(glm::dvec3(light.position), 1.0);
}

bool facesLight(const glm::dvec4& light, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const glm::dvec3 A(a), B(b), C(c);
    return glm::dot(glm::cross(B - A, C - A), towardsLight(light, A)) > 0.0;
}

CasterSigns casterSigns(bool lit, bool closedMesh) {
    if (closedMesh) return lit ? CasterSigns{+1, 0} : CasterSigns{0, +1};
    return lit ? CasterSigns{+1, -1} : CasterSigns{-1, +1};
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

}  // namespace shadowlab
