// World-space bounds of a named instance, for the scene tests that check a case's geometry.
#pragma once

#include <cmath>
#include <string>

#include <doctest/doctest.h>
#include <glm/glm.hpp>

#include "scenes/scene_file.h"

namespace shadowlab::test {

struct Box {
    glm::vec3 lo{INFINITY}, hi{-INFINITY};
};

// World-space bounds of the instance called name; fails the test if there is none.
inline Box instanceBounds(const Scene& scene, const WorldGeometry& world, const std::string& name) {
    Box box;
    for (size_t t = 0; t < world.triangles.size(); ++t) {
        if (scene.instances[world.triangleInstance[t]].name != name) continue;
        for (int c = 0; c < 3; ++c) {
            box.lo = glm::min(box.lo, world.positions[world.triangles[t][c]]);
            box.hi = glm::max(box.hi, world.positions[world.triangles[t][c]]);
        }
    }
    REQUIRE_MESSAGE(box.lo.x <= box.hi.x, "no instance " << name);
    return box;
}

}  // namespace shadowlab::test
