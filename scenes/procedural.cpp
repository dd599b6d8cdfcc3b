#include "scenes/procedural.h"

#include <array>
#include <cmath>
#include <numbers>

#include "raster/portable_math.h"

namespace shadowlab {

Mesh makeGrid(glm::vec2 size, glm::ivec2 divisions) {
    Mesh mesh;
    mesh.source = "procedural:grid";
    const uint32_t rowLength = uint32_t(divisions.x) + 1;
    for (int k = 0; k <= divisions.y; ++k) {
        for (int i = 0; i <= divisions.x; ++i) {
            const double x = (double(i) / divisions.x - 0.5) * size.x;
            const double z = (double(k) / divisions.y - 0.5) * size.y;
            mesh.positions.emplace_back(float(x), 0.0f, float(z));
        }
    }
    for (uint32_t k = 0; k < uint32_t(divisions.y); ++k) {
        for (uint32_t i = 0; i < uint32_t(divisions.x); ++i) {
            // Corners a (x0,z0), b (x0,z1), c (x1,z1), d (x1,z0): (b-a) x (c-a) is +Y.
            const uint32_t a = k * rowLength + i, b = a + rowLength, c = b + 1, d = a + 1;
            mesh.triangles.emplace_back(a, b, c);
            mesh.triangles.emplace_back(a, c, d);
        }
    }
    mesh.cornerNormals.assign(3 * mesh.triangles.size(), glm::vec3(0.0f, 1.0f, 0.0f));
    // u along +x, v along -z: seen from above with -z at the top, the texture upright.
    const auto uvOf = [&](uint32_t vertex) {
        return glm::vec2(float(double(vertex % rowLength) / divisions.x),
                         float(1.0 - double(vertex / rowLength) / divisions.y));
    };
    for (const glm::uvec3& t : mesh.triangles) {
        mesh.cornerUvs.insert(mesh.cornerUvs.end(), {uvOf(t.x), uvOf(t.y), uvOf(t.z)});
    }
    return mesh;
}

Mesh makeUvSphere(float radius, int slices, int stacks) {
    Mesh mesh;
    mesh.source = "procedural:uv-sphere";
    const double r = radius;
    // Longitude phi runs counter-clockwise seen from +Y (x towards -z), latitude theta
    // from the north pole; the poles are exact so the caps meet in a single point.
    mesh.positions.emplace_back(0.0f, radius, 0.0f);
    for (int k = 1; k < stacks; ++k) {
        const double theta = std::numbers::pi * k / stacks;
        for (int j = 0; j < slices; ++j) {
            const double phi = 2.0 * std::numbers::pi * j / slices;
            mesh.positions.emplace_back(float(r * portable::sin(theta) * portable::cos(phi)),
                                        float(r * portable::cos(theta)),
                                        float(-r * portable::sin(theta) * portable::sin(phi)));
        }
    }
    mesh.positions.emplace_back(0.0f, -radius, 0.0f);

    const uint32_t north = 0, south = uint32_t(mesh.positions.size()) - 1;
    const uint32_t n = uint32_t(slices);
    auto ring = [n](uint32_t k, uint32_t j) { return 1 + (k - 1) * n + j % n; };
    for (uint32_t j = 0; j < n; ++j) mesh.triangles.emplace_back(north, ring(1, j), ring(1, j + 1));
    for (uint32_t k = 1; k + 1 < uint32_t(stacks); ++k) {
        for (uint32_t j = 0; j < n; ++j) {
            const uint32_t upper = ring(k, j), upperNext = ring(k, j + 1);
            const uint32_t lower = ring(k + 1, j), lowerNext = ring(k + 1, j + 1);
            mesh.triangles.emplace_back(upper, lower, lowerNext);
            mesh.triangles.emplace_back(upper, lowerNext, upperNext);
        }
    }
    const uint32_t last = uint32_t(stacks) - 1;
    for (uint32_t j = 0; j < n; ++j) mesh.triangles.emplace_back(south, ring(last, j + 1), ring(last, j));
    // The sphere's own normal at each vertex, p / r (computed from the float position in
    // double, so it is unit to the last bit a float holds).
    for (const glm::uvec3& t : mesh.triangles)
        for (int c = 0; c < 3; ++c) mesh.cornerNormals.push_back(glm::vec3(glm::normalize(glm::dvec3(mesh.positions[t[c]]))));
    return mesh;
}

Mesh makeBox(glm::vec3 min, glm::vec3 max) {
    Mesh mesh;
    mesh.source = "procedural:box";
    // Corner c has x from bit 0, y from bit 1, z from bit 2 (0 = min, 1 = max).
    for (int c = 0; c < 8; ++c)
        mesh.positions.emplace_back(c & 1 ? max.x : min.x, c & 2 ? max.y : min.y, c & 4 ? max.z : min.z);
    // Each face as a quad, counter-clockwise seen from outside: -X, +X, -Y, +Y, -Z, +Z.
    constexpr std::array<std::array<uint32_t, 4>, 6> kFaces{{
        {0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}}};
    // A box is flat: each corner of a face shades with the face's normal.
    constexpr std::array<glm::vec3, 6> kFaceNormals{{
        {-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}}};
    for (size_t f = 0; f < kFaces.size(); ++f) {
        const auto& q = kFaces[f];
        mesh.triangles.emplace_back(q[0], q[1], q[2]);
        mesh.triangles.emplace_back(q[0], q[2], q[3]);
        mesh.cornerNormals.insert(mesh.cornerNormals.end(), 6, kFaceNormals[f]);
    }
    return mesh;
}

}  // namespace shadowlab
