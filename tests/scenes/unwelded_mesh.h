// A triangle soup of a mesh, for the tests of welding and of what is built on it.
#pragma once

#include "scenes/scene.h"

namespace shadowlab::test {

// The same mesh with every triangle given its own three vertices: only welding finds edges.
inline Mesh unwelded(const Mesh& mesh) {
    Mesh soup;
    for (const glm::uvec3& t : mesh.triangles) {
        const uint32_t base = uint32_t(soup.positions.size());
        for (int k = 0; k < 3; ++k) soup.positions.push_back(mesh.positions[t[k]]);
        soup.triangles.emplace_back(base, base + 1, base + 2);
    }
    return soup;
}

}  // namespace shadowlab::test
