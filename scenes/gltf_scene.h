// glTF 2.0 files (.gltf with external or embedded buffers, .glb) as scenes
// (docs/scene-format.md, "glTF files"), read with tinygltf in stages, one file each in
// scenes/gltf/: the document and its checks, accessors, primitives, nodes, materials,
// lights (KHR_lights_punctual) and cameras; this puts them together.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "scenes/scene.h"

namespace shadowlab {

// What a glTF file holds, as our scene's parts: one mesh per (primitive, mirrored or not),
// one instance per (node, primitive) placed by the node's world transform, materials with
// their cut-outs' alpha textures and their albedo textures (Material::alphaTexture and
// Material::albedoTexture index alphaTextures and albedoTextures here), the
// lights of KHR_lights_punctual and the first camera, in the scene's node order.
struct GltfModel {
    std::vector<Mesh> meshes;
    std::vector<Material> materials;
    std::vector<AlphaTexture> alphaTextures;
    std::vector<AlbedoTexture> albedoTextures;
    std::vector<MeshInstance> instances;
    std::vector<Light> lights;
    std::optional<Camera> camera;   // zFar 0: the file gave none (gltf/gltf_camera.h)
    // What the file holds that is not read (docs/scene-format.md, "Ignored, by name"): its
    // skins, animations, morph targets, cameras after the first, extensions used but not
    // read; appendGltfModel tells them in scene.notes.
    std::vector<std::string> ignored;
};

// Throws SceneError naming the file and the field for anything it cannot read.
GltfModel readGltfModel(const std::string& path);
// The same from bytes in memory (the fuzzer); external files are found beside `path`.
GltfModel parseGltfModel(const std::string& bytes, const std::string& path);

// Appends the model's meshes, materials, their textures and instances to the scene, each
// instance placed by `placement` * its node's transform, with `material` (an index into
// the scene's materials) in place of the file's when given, and what it ignores to
// scene.notes. Refuses, naming `name`, a vertex outside the world (scene_limits.h).
void appendGltfModel(const GltfModel& model, const glm::mat4& placement, std::optional<uint32_t> material,
                     const std::string& name, Scene& scene);

// The model as a scene to render (`shadowlab render model.glb`): its camera and lights,
// or, where it has none, defaults said in scene.notes (docs/scene-format.md, "glTF files"):
// a camera that frames the scene's bounding sphere, and a sun.
Scene gltfScene(GltfModel model, const std::string& path);
Scene loadGltfScene(const std::string& path);

// Whether a path names a glTF file (.gltf or .glb, any case).
bool isGltfPath(const std::string& path);

}  // namespace shadowlab
