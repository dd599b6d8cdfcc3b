// Readers for the parts of a scene file (docs/scene-format.md), one file per part:
// scene_meshes.cpp, scene_instances.cpp, scene_lights.cpp; scene_file.cpp reads the rest
// and puts them together. Each throws SceneError naming the file and the field path.
#pragma once

#include <string>
#include <vector>

#include "scenes/json_fields.h"
#include "scenes/scene.h"
#include "scenes/scene_limits.h"
#include "scenes/view_rules.h"

namespace shadowlab {

// A procedural mesh's or volume's seed (procedural_casters.h, unitHash).
inline constexpr Interval kSeed{0.0, 2147483647.0, false, false};

// The names the file gives to meshes and materials, parallel to Scene::meshes and
// Scene::materials; instances refer to them by name. And the parts of each placement the
// "instances" entries made (in Scene::instances' order; the instances of "models" come
// after them and have none), which a fly-through's keyframes keep when they give an
// instance a new transform (scene.h, PathInstance).
struct SceneNames {
    std::vector<std::string> meshes, materials;
    std::vector<PathInstance> instanceParts;
};

// One mesh entry: {"file": ...} (OBJ or PLY, relative to directory) or {"procedural": ...}.
Mesh readMesh(const JsonObject& object, const std::string& directory);

// Appends every mesh of the "meshes" array; file paths are relative to directory.
void readMeshes(const JsonField& field, const std::string& directory, Scene& scene, SceneNames& names);

// An instance's or model's transform (docs/scene-format.md, "transform"): translate,
// rotate and scale, or a matrix.
glm::mat4 readTransform(const JsonObject& object);
// Its translate, rotate and scale, each optional (the identity's where absent).
InstancePose readPose(const JsonObject& object);

// Fails on `field` if a vertex of the instance lands outside the world (kCoordinate) as
// flatten() places it.
void checkInWorld(const JsonField& field, const MeshInstance& instance, const Mesh& mesh);

// Appends the instances one entry describes: one, or a lattice of copies with "repeat".
void readInstance(const JsonField& field, SceneNames& names, Scene& scene);

// One entry of "models": a glTF file's meshes, materials and node transforms, placed
// (scene_models.cpp); its file is relative to directory.
void readModel(const JsonField& field, const std::string& directory, const SceneNames& names, Scene& scene);

// A spot light's cookie file is relative to directory.
Light readLight(const JsonField& field, const std::string& directory);

// Fails on a camera object whose view frame is undefined (camera.h, viewFrameProblem),
// naming its "target" or "up" when it has one: the rule of every camera a file holds.
void checkViewFrame(const JsonObject& object, const Camera& camera);

// One entry of "volumes": a procedural density volume (scene_volumes.cpp).
// `voxels`: those of the volumes before it; adds this one's, refusing a sum over
// kMaxSceneVoxels before any voxel is made.
DensityVolume readVolume(const JsonField& field, uint64_t& voxels);

}  // namespace shadowlab
