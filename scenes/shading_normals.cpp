// Angle-weighted vertex normals (Thürmer and Wüthrich 1998) and the corner normals that
// shading interpolates (shading_normals.h).
#include "scenes/shading_normals.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "raster/portable_math.h"

namespace shadowlab {
namespace {

// The angle between edges a and b, robust near 0 and pi where acos of the
// dot product loses all precision: atan2(|a x b|, a . b).
double angleBetween(const glm::dvec3& a, const glm::dvec3& b) {
    return portable::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

glm::dvec3 corner(const Mesh& mesh, const glm::uvec3& t, int c) { return glm::dvec3(mesh.positions[t[c]]); }

glm::vec3 unitOrZero(const glm::dvec3& v) {
    const double length = glm::length(v);
    return length > 0.0 ? glm::vec3(v / length) : glm::vec3(0.0f);
}

}  // namespace

std::vector<glm::vec3> angleWeightedNormals(const Mesh& mesh) {
    std::vector<glm::dvec3> sum(mesh.positions.size(), glm::dvec3(0.0));
    for (const glm::uvec3& t : mesh.triangles) {
        const glm::dvec3 p[3] = {corner(mesh, t, 0), corner(mesh, t, 1), corner(mesh, t, 2)};
        const glm::dvec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
        const double length = glm::length(n);
        if (!(length > 0.0)) continue;   // degenerate: no plane, no angle
        for (int c = 0; c < 3; ++c)
            sum[t[c]] += (n / length) * angleBetween(p[(c + 1) % 3] - p[c], p[(c + 2) % 3] - p[c]);
    }
    std::vector<glm::vec3> normals(sum.size());
    for (size_t v = 0; v < sum.size(); ++v) normals[v] = unitOrZero(sum[v]);
    return normals;
}

std::vector<glm::vec3> cornerShadingNormals(const Mesh& mesh) {
    const size_t corners = 3 * mesh.triangles.size();
    if (!mesh.cornerNormals.empty() && mesh.cornerNormals.size() != corners)
        throw std::invalid_argument("cornerShadingNormals: " + mesh.source + " has " +
                                    std::to_string(mesh.cornerNormals.size()) + " corner normals for " +
                                    std::to_string(mesh.triangles.size()) + " triangles");
    // Vertex normals only when some corner needs one (procedural meshes give every corner).
    const bool complete = !mesh.cornerNormals.empty() &&
                          std::ranges::none_of(mesh.cornerNormals, [](const glm::vec3& n) { return n == glm::vec3(0.0f); });
    const std::vector<glm::vec3> vertexNormals = complete ? std::vector<glm::vec3>{} : angleWeightedNormals(mesh);
    std::vector<glm::vec3> normals(corners);
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const glm::uvec3 tri = mesh.triangles[t];
        const glm::vec3 face = unitOrZero(glm::cross(corner(mesh, tri, 1) - corner(mesh, tri, 0),
                                                     corner(mesh, tri, 2) - corner(mesh, tri, 0)));
        for (int c = 0; c < 3; ++c) {
            const glm::vec3 given = mesh.cornerNormals.empty() ? glm::vec3(0.0f) : mesh.cornerNormals[3 * t + c];
            if (!std::isfinite(given.x) || !std::isfinite(given.y) || !std::isfinite(given.z))
                throw std::invalid_argument("cornerShadingNormals: " + mesh.source + ": triangle " +
                                            std::to_string(t) + " has a non-finite normal");
            glm::vec3 n = unitOrZero(glm::dvec3(given));
            if (n == glm::vec3(0.0f)) n = vertexNormals[tri[c]];
            if (n == glm::vec3(0.0f)) n = face;
            normals[3 * t + c] = n;
        }
    }
    return normals;
}

glm::dmat3 normalMatrix(const MeshInstance& instance) {
    const glm::dmat3 m(glm::mat3(instance.worldFromObject));
    return glm::dmat3(glm::cross(m[1], m[2]), glm::cross(m[2], m[0]), glm::cross(m[0], m[1]));
}

glm::vec3 worldNormal(const glm::dmat3& normalMatrix, const glm::vec3& n) {
    return unitOrZero(normalMatrix * glm::dvec3(n));
}

}  // namespace shadowlab
