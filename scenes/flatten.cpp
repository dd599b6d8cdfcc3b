// flatten(): the world-space triangle list that every technique renders, and where each
// instance lies in it (scene.h).
#include <optional>
#include <span>
#include <stdexcept>

#include "scenes/scene.h"
#include "scenes/shading_normals.h"

namespace shadowlab {
namespace {

// Every per-vertex and per-corner array at its full length, so that placeInstance writes
// each instance's part in place; the per-triangle ones are appended.
void sizeFor(const Scene& scene, WorldGeometry& world) {
    size_t vertices = 0, triangles = 0;
    for (const MeshInstance& instance : scene.instances) {
        vertices += scene.meshes[instance.mesh].positions.size();
        triangles += scene.meshes[instance.mesh].triangles.size();
    }
    world.positions.resize(vertices);
    world.triangles.reserve(triangles);
    world.triangleMaterial.reserve(triangles);
    world.triangleInstance.reserve(triangles);
    world.cornerNormals.resize(3 * triangles);
}

// The instance's material, or null where a scene made in code has none for it (only
// shading reads materials otherwise).
const Material* materialOf(const Scene& scene, const MeshInstance& instance) {
    return instance.material < scene.materials.size() ? &scene.materials[instance.material] : nullptr;
}

// Whether any instance's material passes `test`.
template <class Test>
bool anyMaterial(const Scene& scene, const Test& test) {
    for (const MeshInstance& instance : scene.instances) {
        const Material* material = materialOf(scene, instance);
        if (material && test(*material)) return true;
    }
    return false;
}

// The index in world.cutOuts of a material's alpha test, added on first use; -1 for a
// material that is no cut-out.
int32_t cutOutOf(const Scene& scene, uint32_t material, std::vector<int32_t>& materialCutOut, WorldGeometry& world) {
    if (material >= scene.materials.size() || !scene.materials[material].cutOut()) return -1;
    const Material& m = scene.materials[material];
    if (materialCutOut[material] < 0) {
        const AlphaTexture& texture = scene.alphaTextures[size_t(m.alphaTexture)];
        materialCutOut[material] = int32_t(world.cutOuts.size());
        world.cutOuts.push_back({texture.alpha, texture.width, texture.height, m.alphaCutoff, texture.wrap});
    }
    return materialCutOut[material];
}

}  // namespace

bool hasNonOpaqueCasters(const Scene& scene) {
    if (!scene.volumes.empty()) return true;
    for (const MeshInstance& instance : scene.instances) {
        const Material* material = materialOf(scene, instance);
        if (material && (material->translucent() || material->cutOut())) return true;
    }
    return false;
}

WorldGeometry flatten(const Scene& scene) {
    WorldGeometry world;
    sizeFor(scene, world);
    // Each mesh's corner normals once, however many instances use it.
    std::vector<std::optional<std::vector<glm::vec3>>> meshNormals(scene.meshes.size());
    const bool cutOuts = anyMaterial(scene, [](const Material& m) { return m.cutOut(); });
    // Texture coordinates are kept only for what reads them: cut-outs' alpha, surfaces' albedo.
    const bool uvs = cutOuts || anyMaterial(scene, [](const Material& m) { return m.textured(); });
    std::vector<int32_t> materialCutOut(scene.materials.size(), -1);
    const std::vector<InstanceRange> ranges = instanceRanges(scene);
    for (uint32_t i = 0; i < scene.instances.size(); ++i) {
        const MeshInstance& instance = scene.instances[i];
        const Mesh& mesh = scene.meshes[instance.mesh];
        const int32_t cutOut = cutOuts ? cutOutOf(scene, instance.material, materialCutOut, world) : -1;
        for (const glm::uvec3& t : mesh.triangles) {
            if (cutOuts) world.triangleCutOut.push_back(cutOut);
            world.triangles.push_back(t + ranges[i].firstVertex);
            world.triangleMaterial.push_back(instance.material);
            world.triangleInstance.push_back(i);
        }
        if (!meshNormals[instance.mesh]) meshNormals[instance.mesh] = cornerShadingNormals(mesh);
        placeInstance(instance, mesh, *meshNormals[instance.mesh], ranges[i], world);
        if (!uvs) continue;
        if (!mesh.cornerUvs.empty() && mesh.cornerUvs.size() != 3 * mesh.triangles.size())
            throw std::invalid_argument("flatten: mesh " + mesh.source + " has texture coordinates for some corners only");
        if (mesh.cornerUvs.empty()) world.cornerUvs.resize(world.cornerUvs.size() + 3 * mesh.triangles.size());
        world.cornerUvs.insert(world.cornerUvs.end(), mesh.cornerUvs.begin(), mesh.cornerUvs.end());
    }
    return world;
}

void placeInstance(const MeshInstance& instance, const Mesh& mesh, std::span<const glm::vec3> objectNormals,
                   const InstanceRange& range, WorldGeometry& world) {
    for (size_t k = 0; k < mesh.positions.size(); ++k)
        world.positions[range.firstVertex + k] = worldPosition(instance, mesh.positions[k]);
    const glm::dmat3 toWorld = normalMatrix(instance);
    const size_t firstCorner = 3 * size_t(range.firstTriangle);
    for (size_t c = 0; c < objectNormals.size(); ++c)
        world.cornerNormals[firstCorner + c] = worldNormal(toWorld, objectNormals[c]);
}

std::vector<InstanceRange> instanceRanges(const Scene& scene) {
    std::vector<InstanceRange> ranges;
    uint32_t vertex = 0, triangle = 0;
    for (const MeshInstance& instance : scene.instances) {
        const Mesh& mesh = scene.meshes[instance.mesh];
        ranges.push_back({instance.mesh, vertex, triangle, uint32_t(mesh.triangles.size())});
        vertex += uint32_t(mesh.positions.size());
        triangle += uint32_t(mesh.triangles.size());
    }
    return ranges;
}

}  // namespace shadowlab
