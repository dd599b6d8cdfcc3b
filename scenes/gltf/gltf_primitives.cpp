#include "scenes/gltf/gltf_primitives.h"

#include <cmath>

#include "scenes/gltf/gltf_accessors.h"
#include "scenes/scene_limits.h"

namespace shadowlab {
namespace {

// A unit normal read from a file may be off by rounding; beyond this it is not a normal.
constexpr float kUnitTolerance = 1e-3f;

// Corner k of triangle t of each mode (section 3.7.2.1): strip p_i = {v_i, v_{i+1+i%2},
// v_{i+2-i%2}}, which keeps every triangle counter-clockwise; fan p_i = {v_{i+1}, v_{i+2}, v_0}.
std::vector<glm::uvec3> assemble(int mode, const std::vector<uint32_t>& v) {
    std::vector<glm::uvec3> triangles;
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        triangles.reserve(v.size() / 3);
        for (size_t i = 0; i + 2 < v.size(); i += 3) triangles.emplace_back(v[i], v[i + 1], v[i + 2]);
    } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
        for (size_t i = 0; i + 2 < v.size(); ++i)
            triangles.emplace_back(v[i], v[i + 1 + i % 2], v[i + 2 - i % 2]);
    } else {
        for (size_t i = 0; i + 2 < v.size(); ++i) triangles.emplace_back(v[i + 1], v[i + 2], v[0]);
    }
    return triangles;
}

std::vector<uint32_t> sequence(uint64_t count) {
    std::vector<uint32_t> v(count);
    for (size_t k = 0; k < v.size(); ++k) v[k] = uint32_t(k);
    return v;
}

// Per-vertex attribute values, one per corner of each triangle.
template <typename T>
std::vector<T> perCorner(const std::vector<T>& values, const std::vector<glm::uvec3>& triangles) {
    std::vector<T> corners;
    corners.reserve(3 * triangles.size());
    for (const glm::uvec3& t : triangles)
        for (int c = 0; c < 3; ++c) corners.push_back(values[t[c]]);
    return corners;
}

}  // namespace

std::optional<Mesh> readPrimitive(const GltfDocument& document, size_t meshIndex, size_t primitiveIndex) {
    const tinygltf::Primitive& primitive = document.model.meshes[meshIndex].primitives[primitiveIndex];
    const std::string field = "meshes[" + std::to_string(meshIndex) + "].primitives[" + std::to_string(primitiveIndex) + "]";
    const int mode = primitive.mode;
    if (mode >= TINYGLTF_MODE_POINTS && mode <= TINYGLTF_MODE_LINE_STRIP) return std::nullopt;
    if (mode < TINYGLTF_MODE_TRIANGLES || mode > TINYGLTF_MODE_TRIANGLE_FAN)
        document.fail(field + ".mode", std::to_string(mode) + " is not a primitive mode (0 to 6)");
    const auto position = primitive.attributes.find("POSITION");
    if (position == primitive.attributes.end()) document.fail(field + ".attributes", "has no POSITION");
    Mesh mesh;
    mesh.source = document.path + ": " + field;
    mesh.positions = readVec3Accessor(document, position->second, field + ".attributes.POSITION");
    const uint64_t vertices = mesh.positions.size();
    const std::vector<uint32_t> corners =
        primitive.indices >= 0 ? readIndexAccessor(document, primitive.indices, vertices, field + ".indices")
                               : sequence(vertices);
    const std::string countField = primitive.indices >= 0 ? field + ".indices" : field + ".attributes.POSITION";
    if (mode == TINYGLTF_MODE_TRIANGLES && corners.size() % 3 != 0)
        document.fail(countField, std::to_string(corners.size()) + " vertices do not make whole triangles (TRIANGLES)");
    if (corners.size() < 3) document.fail(countField, std::to_string(corners.size()) + " vertices make no triangle");
    mesh.triangles = assemble(mode, corners);
    if (mesh.triangles.size() > kMaxSceneTriangles)
        document.fail(countField, "more triangles than a scene may hold (" + std::to_string(kMaxSceneTriangles) + ")");
    for (const char* name : {"NORMAL", "TEXCOORD_0"}) {
        const auto attribute = primitive.attributes.find(name);
        if (attribute == primitive.attributes.end()) continue;
        const std::string attributeField = field + ".attributes." + name;
        if (accessorCount(document, attribute->second, attributeField) != vertices)
            document.fail(attributeField, "has " + std::to_string(accessorCount(document, attribute->second, attributeField)) +
                                              " elements but POSITION has " + std::to_string(vertices));
        if (std::string(name) == "NORMAL") {
            const std::vector<glm::vec3> normals = readVec3Accessor(document, attribute->second, attributeField);
            for (size_t k = 0; k < normals.size(); ++k) {
                if (!(std::abs(glm::length(normals[k]) - 1.0f) <= kUnitTolerance))
                    document.fail(attributeField, "normal " + std::to_string(k) + " has length " +
                                                      std::to_string(glm::length(normals[k])) + ", not 1");
            }
            mesh.cornerNormals = perCorner(normals, mesh.triangles);
        } else {
            std::vector<glm::vec2> uvs = readTexcoordAccessor(document, attribute->second, attributeField);
            for (glm::vec2& uv : uvs) uv.y = 1.0f - uv.y;   // glTF's (0, 0) is the image's top-left
            mesh.cornerUvs = perCorner(uvs, mesh.triangles);
        }
    }
    return mesh;
}

Mesh mirrored(Mesh mesh) {
    // flatten() turns normals by the cofactor matrix (scenes/shading_normals.h), which a
    // mirror's negative determinant negates: the file's normals are negated here to match.
    for (glm::vec3& n : mesh.cornerNormals) n = -n;
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        std::swap(mesh.triangles[t][1], mesh.triangles[t][2]);
        if (!mesh.cornerNormals.empty()) std::swap(mesh.cornerNormals[3 * t + 1], mesh.cornerNormals[3 * t + 2]);
        if (!mesh.cornerUvs.empty()) std::swap(mesh.cornerUvs[3 * t + 1], mesh.cornerUvs[3 * t + 2]);
    }
    return mesh;
}

}  // namespace shadowlab
