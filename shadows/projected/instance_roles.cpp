#include "shadows/projected/instance_roles.h"

#include <stdexcept>

namespace shadowlab {
namespace {

std::string knownNames(const Scene& scene) {
    std::string known;
    for (const MeshInstance& instance : scene.instances) {
        if (!known.empty()) known += ", ";
        known += instance.name;
    }
    return known;
}

std::vector<uint8_t> named(const Scene& scene, const std::vector<std::string>& names, const char* role) {
    std::vector<uint8_t> chosen(scene.instances.size(), 0);
    for (const std::string& name : names) {
        bool found = false;
        for (size_t k = 0; k < scene.instances.size(); ++k) {
            if (scene.instances[k].name == name) chosen[k] = 1, found = true;
        }
        if (!found) {
            std::string message = "projected-texture: ";
            message += role;
            message += " names no instance \"";
            message += name;
            message += "\" (instances: ";
            message += knownNames(scene);
            message += ")";
            throw std::invalid_argument(message);
        }
    }
    return chosen;
}

// The instances named "ground", or else the one with the largest surface area (the first
// of equals): what a receiver usually is in a scene with one floor.
std::vector<uint8_t> defaultReceivers(const Scene& scene, const WorldGeometry& world) {
    std::vector<uint8_t> chosen(scene.instances.size(), 0);
    bool anyGround = false;
    for (size_t k = 0; k < scene.instances.size(); ++k) {
        if (scene.instances[k].name == "ground") chosen[k] = 1, anyGround = true;
    }
    if (anyGround || scene.instances.empty()) return chosen;
    std::vector<double> area(scene.instances.size(), 0.0);
    for (size_t t = 0; t < world.triangles.size(); ++t) {
        const glm::dvec3 a(world.positions[world.triangles[t].x]), b(world.positions[world.triangles[t].y]),
            c(world.positions[world.triangles[t].z]);
        area[world.triangleInstance[t]] += 0.5 * glm::length(glm::cross(b - a, c - a));
    }
    size_t largest = 0;
    for (size_t k = 1; k < area.size(); ++k) largest = area[k] > area[largest] ? k : largest;
    chosen[largest] = 1;
    return chosen;
}

}  // namespace

InstanceRoles chooseRoles(const Scene& scene, const WorldGeometry& world,
                          const std::optional<std::vector<std::string>>& occluders,
                          const std::optional<std::vector<std::string>>& receivers) {
    InstanceRoles roles;
    roles.receiver = receivers ? named(scene, *receivers, "receivers") : defaultReceivers(scene, world);
    if (occluders) {
        roles.occluder = named(scene, *occluders, "occluders");
    } else {
        for (const uint8_t r : roles.receiver) roles.occluder.push_back(!r);
    }
    for (size_t k = 0; k < scene.instances.size(); ++k) {
        if (roles.occluder[k] && roles.receiver[k]) {
            std::string message = "projected-texture: instance \"";
            message += scene.instances[k].name;
            message += "\" is both an occluder and a receiver (it would shadow its own lit side)";
            throw std::invalid_argument(message);
        }
    }
    return roles;
}

std::vector<uint32_t> trianglesWithRole(const WorldGeometry& world, const std::vector<uint8_t>& role) {
    std::vector<uint32_t> triangles;
    for (uint32_t t = 0; t < world.triangles.size(); ++t) {
        if (role[world.triangleInstance[t]]) triangles.push_back(t);
    }
    return triangles;
}

}  // namespace shadowlab
