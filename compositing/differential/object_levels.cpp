#include "compositing/differential/object_levels.h"

#include <algorithm>
#include <stdexcept>

namespace shadowlab {

ObjectLevels objectLevels(const SyntheticObject& object, int shadowTriangles) {
    if (object.mesh.triangles.empty()) throw std::invalid_argument("synthetic object: its mesh has no triangle");
    if (shadowTriangles < 4) throw std::invalid_argument("synthetic object: a shadow level needs 4 triangles or more");
    Scene whole;
    whole.name = "synthetic object";
    whole.meshes = {object.mesh};
    whole.materials = {Material{"object", MaterialModel::Lambert, glm::vec3(object.albedo)}};
    whole.instances = {MeshInstance{"object", 0, 0, glm::mat4(1.0f)}};
    const double ratio = std::min(1.0, double(shadowTriangles) / double(object.mesh.triangles.size()));
    SimplifiedScene simplified = simplifyMeshes(whole, ratio);
    return {std::move(whole), std::move(simplified)};
}

WorldGeometry placed(const Scene& level, const glm::mat4& placement) {
    Scene copy = level;
    for (MeshInstance& instance : copy.instances) instance.worldFromObject = placement;
    return flatten(copy);
}

double largestScale(const glm::mat4& placement) {
    const glm::dmat3 m(placement);
    return std::max({glm::length(m[0]), glm::length(m[1]), glm::length(m[2])});
}

}  // namespace shadowlab
