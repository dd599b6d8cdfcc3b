#include "differential/object_levels.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "scenes/float_range.h"

namespace shadowlab {
namespace {

void requireValid(std::span<const SyntheticObject> objects, int shadowTriangles) {
    if (objects.empty()) throw std::invalid_argument("synthetic objects: there is none");
    if (shadowTriangles < 4) throw std::invalid_argument("synthetic objects: a shadow level needs 4 triangles or more");
    for (size_t i = 0; i < objects.size(); ++i) {
        const std::string who = "synthetic object " + std::to_string(i) + ": ";
        if (objects[i].mesh.triangles.empty()) throw std::invalid_argument(who + "its mesh has no triangle");
        if (objects[i].path.empty()) throw std::invalid_argument(who + "its path has no frame");
        if (objects[i].path.size() != objects[0].path.size())
            throw std::invalid_argument(who + "its path is not as long as the first's");
        requireFinitePlacements(objects[i].path, "synthetic object " + std::to_string(i));
    }
}

}  // namespace

ObjectLevels objectLevels(std::span<const SyntheticObject> objects, int shadowTriangles) {
    requireValid(objects, shadowTriangles);
    Scene whole;
    whole.name = "synthetic objects";
    size_t triangles = 0;
    for (uint32_t i = 0; i < objects.size(); ++i) {
        const std::string name = "object " + std::to_string(i);
        whole.meshes.push_back(objects[i].mesh);
        whole.materials.push_back(Material{name, MaterialModel::Lambert, glm::vec3(objects[i].albedo)});
        whole.instances.push_back(MeshInstance{name, i, i, glm::mat4(1.0f)});
        triangles += objects[i].mesh.triangles.size();
    }
    // One ratio for all: each object keeps its share of the shadow triangles.
    const double ratio = std::min(1.0, double(shadowTriangles) / double(triangles));
    SimplifiedScene simplified = simplifyMeshes(whole, ratio);
    return {std::move(whole), std::move(simplified)};
}

void requireFinitePlacements(std::span<const glm::mat4> placements, const std::string& who) {
    for (const glm::mat4& placement : placements) {
        if (!allFinite(placement)) throw std::invalid_argument(who + ": a placement is not finite");
    }
}

std::vector<glm::mat4> placementsAt(std::span<const SyntheticObject> objects, size_t frame) {
    std::vector<glm::mat4> placements;
    for (const SyntheticObject& object : objects) placements.push_back(object.path.at(frame));
    return placements;
}

WorldGeometry placed(const Scene& level, std::span<const glm::mat4> placements) {
    if (placements.size() != level.instances.size()) {
        throw std::invalid_argument("synthetic objects: " + std::to_string(placements.size()) + " placements for " +
                                    std::to_string(level.instances.size()) + " objects");
    }
    Scene copy = level;
    for (size_t i = 0; i < copy.instances.size(); ++i) copy.instances[i].worldFromObject = placements[i];
    return flatten(copy);
}

double largestScale(std::span<const glm::mat4> placements) {
    double largest = 0.0;
    for (const glm::mat4& placement : placements) {
        const glm::dmat3 m(placement);
        largest = std::max({largest, glm::length(m[0]), glm::length(m[1]), glm::length(m[2])});
    }
    return largest;
}

}  // namespace shadowlab
