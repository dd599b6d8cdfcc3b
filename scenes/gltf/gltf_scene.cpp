// Putting a glTF file's stages together (scenes/gltf_scene.h): meshes per primitive,
// instances per node, materials, lights and the camera; and the defaults of a file drawn
// on its own.
#include "scenes/gltf_scene.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <map>
#include <numbers>
#include <tuple>

#include "scenes/error_text.h"
#include "scenes/gltf/gltf_camera.h"
#include "scenes/gltf/gltf_document.h"
#include "scenes/gltf/gltf_lights.h"
#include "scenes/gltf/gltf_materials.h"
#include "scenes/gltf/gltf_nodes.h"
#include "scenes/gltf/gltf_primitives.h"
#include "scenes/read_file.h"
#include "scenes/scene_error.h"
#include "scenes/scene_limits.h"

namespace shadowlab {
namespace {

// Where the model's materials and meshes went in GltfModel, read on first use: a file's
// material or primitive is read once however many nodes use it.
class ModelBuilder {
public:
    explicit ModelBuilder(const GltfDocument& document) : document_(document) {}

    // Our material for glTF material `index` (-1: the default), or none when it is invisible.
    std::optional<uint32_t> material(int index) {
        const auto found = materials_.find(index);
        if (found != materials_.end()) return found->second;
        GltfMaterial read = readGltfMaterial(document_, index);
        std::optional<uint32_t> ours;
        if (!read.invisible) {
            if (read.alphaTexture) {
                read.material.alphaTexture = int(model.alphaTextures.size());
                model.alphaTextures.push_back(std::move(*read.alphaTexture));
            }
            if (read.albedoTexture) {
                read.material.albedoTexture = int(model.albedoTextures.size());
                model.albedoTextures.push_back(std::move(*read.albedoTexture));
            }
            ours = uint32_t(model.materials.size());
            model.materials.push_back(read.material);
        }
        return materials_[index] = ours;
    }

    // Our mesh for a primitive, its winding reversed under a mirroring node; none for lines
    // and points.
    std::optional<uint32_t> mesh(size_t meshIndex, size_t primitive, bool mirror) {
        const auto key = std::make_tuple(meshIndex, primitive, mirror);
        const auto found = meshes_.find(key);
        if (found != meshes_.end()) return found->second;
        std::optional<Mesh> read = readPrimitive(document_, meshIndex, primitive);
        std::optional<uint32_t> ours;
        if (read) {
            ours = uint32_t(model.meshes.size());
            model.meshes.push_back(mirror ? mirrored(std::move(*read)) : std::move(*read));
        }
        return meshes_[key] = ours;
    }

    GltfModel model;

private:
    const GltfDocument& document_;
    std::map<int, std::optional<uint32_t>> materials_;
    std::map<std::tuple<size_t, size_t, bool>, std::optional<uint32_t>> meshes_;
};

// One instance per drawn primitive of the node's mesh. A node whose transform flattens it
// (determinant 0) draws nothing; skins are ignored: the mesh in its node's static pose.
struct WorldCounts {
    uint64_t triangles = 0, vertices = 0;
};

void addNodeMesh(const GltfDocument& document, const PlacedNode& placed, ModelBuilder& builder, WorldCounts& counts) {
    const tinygltf::Node& node = document.model.nodes[placed.node];
    const std::string field = "nodes[" + std::to_string(placed.node) + "]";
    if (node.mesh < 0) return;
    if (size_t(node.mesh) >= document.model.meshes.size())
        document.fail(field + ".mesh", "names mesh " + std::to_string(node.mesh) + ", but the file has " +
                                           std::to_string(document.model.meshes.size()));
    const double determinant = glm::determinant(glm::dmat3(placed.worldFromNode));
    if (!std::isfinite(determinant)) document.fail(field, "its world transform is not finite");
    if (determinant == 0.0) return;
    const tinygltf::Mesh& mesh = document.model.meshes[size_t(node.mesh)];
    for (size_t p = 0; p < mesh.primitives.size(); ++p) {
        const std::string primitiveField = "meshes[" + std::to_string(node.mesh) + "].primitives[" + std::to_string(p) + "]";
        const std::optional<uint32_t> ours = builder.mesh(size_t(node.mesh), p, determinant < 0.0);
        if (!ours) continue;
        const std::optional<uint32_t> material = builder.material(mesh.primitives[p].material);
        if (!material) continue;
        GltfModel& model = builder.model;
        if ((model.materials[*material].cutOut() || model.materials[*material].textured()) &&
            model.meshes[*ours].cornerUvs.empty())
            document.fail(primitiveField + ".attributes", "its material's base colour texture needs TEXCOORD_0");
        counts.triangles += model.meshes[*ours].triangles.size();
        counts.vertices += model.meshes[*ours].positions.size();
        if (counts.triangles > kMaxSceneTriangles || counts.vertices > kMaxSceneVertices ||
            model.instances.size() >= kMaxInstances)
            document.fail(field, "the scene's instances pass a limit (" + std::to_string(kMaxSceneTriangles) +
                                     " triangles, " + std::to_string(kMaxSceneVertices) + " vertices, " +
                                     std::to_string(kMaxInstances) + " instances)");
        std::string name = node.name.empty() ? field : node.name;
        if (mesh.primitives.size() > 1) name += "/primitive " + std::to_string(p);
        model.instances.push_back({name, *ours, *material, glm::mat4(placed.worldFromNode)});
    }
}

// A sphere around every vertex the instances place (centre of their box).
std::pair<glm::dvec3, double> sceneSphere(const Scene& scene) {
    glm::dvec3 lo(INFINITY), hi(-INFINITY);
    for (const MeshInstance& instance : scene.instances)
        for (const glm::vec3& p : scene.meshes[instance.mesh].positions) {
            const glm::dvec3 w(worldPosition(instance, p));
            lo = glm::min(lo, w), hi = glm::max(hi, w);
        }
    return {0.5 * (lo + hi), std::max(0.5 * glm::length(hi - lo), 1e-3)};
}

// The default camera: 45 degrees, looking at the sphere's centre from the front, right and
// above (glTF's front is +Z, up +Y), far enough that the whole sphere is in view.
Camera framingCamera(const glm::dvec3& centre, double radius) {
    Camera camera;
    camera.fovyDeg = 45.0f;
    const double distance = 1.1 * radius / std::sin(0.5 * 45.0 * std::numbers::pi / 180.0);
    camera.eye = glm::vec3(centre + distance * glm::normalize(glm::dvec3(0.5, 0.5, 1.0)));
    camera.target = glm::vec3(centre);
    camera.zNear = float(std::max(distance - radius, 1e-3 * distance) * 0.5);
    camera.zFar = float((distance + radius) * 1.5);
    return camera;
}

}  // namespace

bool isGltfPath(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::ranges::transform(extension, extension.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return extension == ".gltf" || extension == ".glb";
}

// What the file holds that we do not read, by name and count, so that a user is told that a
// character stands in its bind pose rather than left to wonder.
std::vector<std::string> ignoredParts(const tinygltf::Model& file) {
    std::vector<std::string> ignored;
    const auto count = [&](size_t n, const std::string& what) {
        if (n > 0) ignored.push_back(std::to_string(n) + " " + what);
    };
    size_t morphed = 0;
    for (const tinygltf::Mesh& mesh : file.meshes) {
        for (const tinygltf::Primitive& primitive : mesh.primitives) morphed += !primitive.targets.empty();
    }
    count(file.skins.size(), "skin(s) (the meshes in their nodes' static pose)");
    count(file.animations.size(), "animation(s)");
    count(morphed, "primitive(s) with morph targets (their base shape)");
    count(file.cameras.size() > 1 ? file.cameras.size() - 1 : 0, "camera(s) after the first");
    for (const std::string& extension : file.extensionsUsed) {
        if (extension != "KHR_lights_punctual") ignored.push_back("extension " + extension);
    }
    return ignored;
}

GltfModel parseGltfModel(const std::string& bytes, const std::string& path) {
    const GltfDocument document = parseGltfDocument(bytes, path);
    ModelBuilder builder(document);
    WorldCounts counts;
    for (const PlacedNode& placed : placeNodes(document)) {
        if (!builder.model.camera) builder.model.camera = readNodeCamera(document, placed.node, placed.worldFromNode);
        if (const std::optional<Light> light = readNodeLight(document, placed.node, placed.worldFromNode)) {
            // A frame keeps a V per light (docs/many-lights.md), so the file's lights are bounded as a scene file's.
            if (builder.model.lights.size() == kMaxSceneLights)
                document.fail("nodes[" + std::to_string(placed.node) + "].extensions.KHR_lights_punctual",
                              "places more lights than a scene may hold (" + std::to_string(kMaxSceneLights) + ")");
            builder.model.lights.push_back(*light);
        }
        addNodeMesh(document, placed, builder, counts);
    }
    if (counts.triangles == 0) document.fail("scenes", "the file's scene has no triangles to draw");
    builder.model.ignored = ignoredParts(document.model);
    return std::move(builder.model);
}

GltfModel readGltfModel(const std::string& path) { return parseGltfModel(readWholeFile(path), path); }

void appendGltfModel(const GltfModel& model, const glm::mat4& placement, std::optional<uint32_t> material,
                     const std::string& name, Scene& scene) {
    const uint32_t meshBase = uint32_t(scene.meshes.size()), materialBase = uint32_t(scene.materials.size());
    const int alphaBase = int(scene.alphaTextures.size()), albedoBase = int(scene.albedoTextures.size());
    scene.meshes.insert(scene.meshes.end(), model.meshes.begin(), model.meshes.end());
    scene.alphaTextures.insert(scene.alphaTextures.end(), model.alphaTextures.begin(), model.alphaTextures.end());
    scene.albedoTextures.insert(scene.albedoTextures.end(), model.albedoTextures.begin(), model.albedoTextures.end());
    if (!material) {
        for (Material m : model.materials) {
            if (m.cutOut()) m.alphaTexture += alphaBase;
            if (m.textured()) m.albedoTexture += albedoBase;
            m.name = name + "/" + m.name;
            scene.materials.push_back(m);
        }
    }
    if (scene.instances.size() + model.instances.size() > kMaxInstances)
        throw SceneError(name + ": more instances than a scene may hold (" + std::to_string(kMaxInstances) + ")");
    for (MeshInstance instance : model.instances) {
        instance.name = name + "/" + instance.name;
        instance.mesh += meshBase;
        instance.material = material ? *material : instance.material + materialBase;
        instance.worldFromObject = placement * instance.worldFromObject;
        for (const glm::vec3& p : scene.meshes[instance.mesh].positions) {
            const glm::vec3 w = worldPosition(instance, p);
            if (!(std::abs(w.x) <= kMaxCoordinate && std::abs(w.y) <= kMaxCoordinate && std::abs(w.z) <= kMaxCoordinate))
                throw SceneError(name + ": instance " + inQuotes(instance.name) +
                                 " places a vertex outside the world (coordinates within 1e6 m)");
        }
        scene.instances.push_back(instance);
    }
    if (!model.ignored.empty()) {
        std::string note = name + ": not read:";
        for (size_t k = 0; k < model.ignored.size(); ++k) note += (k ? ", " : " ") + model.ignored[k];
        scene.notes.push_back(note);
    }
}

Scene gltfScene(GltfModel model, const std::string& path) {
    Scene scene;
    scene.name = std::filesystem::path(path).stem().string();
    appendGltfModel(model, glm::mat4(1.0f), std::nullopt, path, scene);
    const auto [centre, radius] = sceneSphere(scene);
    if (model.camera) {
        scene.camera = *model.camera;
        if (scene.camera.zFar == 0.0f)
            scene.camera.zFar = float((glm::length(glm::dvec3(scene.camera.eye) - centre) + radius) * 1.5);
        if (!(scene.camera.zFar > scene.camera.zNear)) scene.camera.zFar = scene.camera.zNear * 2.0f;
    } else {
        scene.camera = framingCamera(centre, radius);
        scene.notes.push_back(path + ": has no camera; framing its bounds from the front, right and above (45 degrees)");
    }
    scene.lights = std::move(model.lights);
    if (scene.lights.empty()) {
        Light sun;
        sun.type = LightType::Directional;
        sun.direction = glm::normalize(glm::vec3(4.0f, 8.0f, 3.0f));
        sun.intensity = glm::vec3(3.0f);
        scene.lights.push_back(sun);
        scene.notes.push_back(path + ": has no KHR_lights_punctual light; lit by a sun towards (4, 8, 3), 3 W/m^2");
    }
    return scene;
}

Scene loadGltfScene(const std::string& path) { return gltfScene(readGltfModel(path), path); }

}  // namespace shadowlab
