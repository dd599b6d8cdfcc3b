#include "scenes/bounds.h"

#include <limits>

namespace shadowlab {

std::vector<Aabb> instanceBounds(const Scene& scene, const WorldGeometry& world) {
    std::vector<Aabb> bounds;
    const double inf = std::numeric_limits<double>::infinity();
    for (const InstanceRange& r : instanceRanges(scene)) {
        Aabb box{glm::dvec3(inf), glm::dvec3(-inf)};
        for (uint32_t v = r.firstVertex; v < r.firstVertex + scene.meshes[r.mesh].positions.size(); ++v) {
            box.min = glm::min(box.min, glm::dvec3(world.positions[v]));
            box.max = glm::max(box.max, glm::dvec3(world.positions[v]));
        }
        bounds.push_back(box);
    }
    return bounds;
}

}  // namespace shadowlab
