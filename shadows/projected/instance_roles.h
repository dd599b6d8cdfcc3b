// Which instances occlude and which receive a projected shadow texture (RTR 4th ed.,
// section 7.2: "the application must identify which objects are occluders and which are
// their receivers"). The technique's parameters name them; by default the receivers are
// the instances named "ground" (the largest instance by surface area when none is), the
// occluders every other instance. An instance may not be both: it would shadow itself
// everywhere the texture covers it, its lit side included, since the texture has no depth.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "scenes/scene.h"

namespace shadowlab {

struct InstanceRoles {
    std::vector<uint8_t> occluder, receiver;   // per instance of Scene::instances, 0 or 1
};

// `occluders` and `receivers` are lists of instance names (a name selects every instance
// so named), nullopt for the default above. Throws std::invalid_argument for a name no
// instance has (listing the names there are) or an instance in both lists.
InstanceRoles chooseRoles(const Scene& scene, const WorldGeometry& world,
                          const std::optional<std::vector<std::string>>& occluders,
                          const std::optional<std::vector<std::string>>& receivers);

// The world's triangles whose instance has the role, ascending (for drawWorld's `only`).
std::vector<uint32_t> trianglesWithRole(const WorldGeometry& world, const std::vector<uint8_t>& role);

}  // namespace shadowlab
