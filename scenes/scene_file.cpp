// Finding and reading scene files (docs/scene-format.md): the top level, materials,
// camera and environment; meshes, instances and lights have a file each.
#include "scenes/scene_file.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <filesystem>

#include "scenes/albedo_texture.h"
#include "scenes/alpha_texture.h"
#include "scenes/camera_path.h"
#include "scenes/error_text.h"
#include "scenes/gltf_scene.h"
#include "scenes/read_file.h"
#include "scenes/scene_file_parts.h"
#include "scenes/scene_limits.h"

namespace shadowlab {
namespace {

namespace fs = std::filesystem;

constexpr std::array<std::pair<std::string_view, MaterialModel>, 4> kMaterialModels{{
    {"lambert", MaterialModel::Lambert}, {"blinn-phong", MaterialModel::BlinnPhong}, {"phong", MaterialModel::Phong},
    {"ggx", MaterialModel::Ggx}}};
constexpr Interval kRoughness{0.0, 1.0, true, false};

constexpr Interval kCutoff{0.0, 1.0, true, false};

// The index in `textures` (the scene's alpha or albedo textures) of the texture the field
// names, relative to the scene file's folder, read by `read` on first use.
template <class Texture>
int textureIndex(const JsonField& field, const std::string& directory, std::vector<Texture>& textures,
                 Texture (*read)(const std::string&)) {
    const std::string path = (fs::path(directory) / field.string()).string();
    for (size_t k = 0; k < textures.size(); ++k) {
        if (textures[k].source == path) return int(k);
    }
    try {
        textures.push_back(read(path));
    } catch (const SceneError& error) {
        field.fail(error);
    }
    return int(textures.size()) - 1;
}

// What passes through a material (scene.h, Material): opacity, its tint and a cut-out.
void readTransmission(const JsonObject& object, const std::string& directory, Scene& scene, Material& material) {
    if (const auto opacity = object.optional("opacity")) material.opacity = opacity->number(kUnitInterval);
    if (const auto tint = object.optional("transmittance")) {
        if (!material.translucent())
            tint->fail("tints the light a translucent surface passes, so needs \"opacity\" < 1");
        material.transmittance = tint->vec3(kUnitInterval);
    }
    if (const auto texture = object.optional("alpha-texture"))
        material.alphaTexture = textureIndex(*texture, directory, scene.alphaTextures, readAlphaTexture);
    if (const auto cutoff = object.optional("alpha-cutoff")) {
        if (!material.cutOut()) cutoff->fail("is the cut-out's threshold, so needs \"alpha-texture\"");
        material.alphaCutoff = cutoff->number(kCutoff);
    }
}

// Each model accepts only its own terms (specular and shininess for Blinn-Phong and Phong,
// specular and roughness for GGX): another model's would be silently ignored.
void readMaterial(const JsonField& field, const std::string& directory, Scene& scene, SceneNames& names) {
    const JsonObject object = field.object();
    Material material;
    const JsonField nameField = object["name"];
    material.name = nameField.string();
    if (std::ranges::find(names.materials, material.name) != names.materials.end())
        nameField.fail("another material is already named " + inQuotes(material.name));
    if (const auto model = object.optional("model")) material.model = model->choice(kMaterialModels);
    std::vector<std::string_view> allowed = {"name", "model", "albedo", "albedo-texture", "opacity", "transmittance",
                                             "alpha-texture", "alpha-cutoff"};
    switch (material.model) {
        case MaterialModel::Lambert: break;
        case MaterialModel::BlinnPhong:
        case MaterialModel::Phong: allowed.insert(allowed.end(), {"specular", "shininess"}); break;
        case MaterialModel::Ggx: allowed.insert(allowed.end(), {"specular", "roughness"}); break;
    }
    object.allowOnly(allowed);
    if (const auto albedo = object.optional("albedo")) material.albedo = albedo->vec3(kUnitInterval);
    if (const auto texture = object.optional("albedo-texture"))
        material.albedoTexture = textureIndex(*texture, directory, scene.albedoTextures, readAlbedoTexture);
    if (const auto specular = object.optional("specular")) material.specular = specular->vec3(kUnitInterval);
    if (const auto shininess = object.optional("shininess")) material.shininess = shininess->number(kPositive);
    if (const auto roughness = object.optional("roughness")) material.roughness = roughness->number(kRoughness);
    readTransmission(object, directory, scene, material);
    scene.materials.push_back(material);
    names.materials.push_back(material.name);
}

Camera readCamera(const JsonField& field) {
    const JsonObject object = field.object({"eye", "target", "up", "fovy", "width", "height", "near", "far"});
    Camera camera;
    camera.eye = object["eye"].vec3(kCoordinate);
    camera.target = object["target"].vec3(kCoordinate);
    if (const auto up = object.optional("up")) camera.up = up->vec3();
    camera.fovyDeg = object["fovy"].number(kFovyDeg);
    camera.width = object["width"].integer(kImageSize);
    camera.height = object["height"].integer(kImageSize);
    if (const auto zNear = object.optional("near")) camera.zNear = zNear->number(kPositive);
    if (const auto zFar = object.optional("far")) camera.zFar = zFar->number(kPositive);
    // The rules that join fields (view_rules.h): near < far, and a view frame.
    if (const auto problem = cameraProblem(camera)) {
        // With far left at its default, the near given is what is at fault.
        const char* field = std::string_view(problem->field) == "far" && !object.has("far") ? "near" : problem->field;
        (object.has(field) ? object[field] : object.field()).fail(problem->problem);
    }
    return camera;
}

// The map must be a file that opens now, so a mistyped name fails at load, naming the field;
// its contents are read by the shading library (scenes/ reads no images).
Environment readEnvironment(const JsonField& field, const std::string& directory) {
    const JsonObject object = field.object({"ambient", "map", "rotation"});
    Environment environment;
    if (const auto ambient = object.optional("ambient")) environment.ambient = ambient->vec3(kNonNegative);
    if (const auto map = object.optional("map")) {
        environment.map = (fs::path(directory) / map->string()).string();
        try {
            regularFileSize(environment.map);   // read when a technique needs it; checked now
        } catch (const SceneError& error) {
            map->fail(error);
        }
    }
    if (const auto rotation = object.optional("rotation")) {
        if (environment.map.empty()) rotation->fail("turns the map, so needs \"map\"");
        environment.rotationDeg = rotation->number({-360.0, 360.0, false, false});
    }
    return environment;
}

// A cut-out needs texture coordinates to find its alpha, a textured material its albedo.
void checkTextureUvs(const JsonField& instances, const Scene& scene) {
    for (size_t k = 0; k < scene.instances.size(); ++k) {
        const MeshInstance& instance = scene.instances[k];
        if (!scene.meshes[instance.mesh].cornerUvs.empty()) continue;
        const Material& material = scene.materials[instance.material];
        if (material.cutOut())
            instances.fail("instance " + inQuotes(instance.name) + " has a cut-out material (alpha-texture) on a mesh without "
                           "texture coordinates");
        if (material.textured())
            instances.fail("instance " + inQuotes(instance.name) + " has a material with an albedo-texture on a mesh "
                           "without texture coordinates");
    }
}

// Nothing to render is a mistake, and a scene beyond the limits (scene_limits.h) would not
// fit the machine; both are found from the meshes and instances, before flattening.
void checkSize(const JsonField& root, const Scene& scene) {
    uint64_t vertices = 0, triangles = 0;
    for (const MeshInstance& instance : scene.instances) {
        vertices += scene.meshes[instance.mesh].positions.size();
        triangles += scene.meshes[instance.mesh].triangles.size();
    }
    if (triangles == 0) root.fail("the scene has no triangles");
    if (triangles > kMaxSceneTriangles)
        root.fail("the scene has " + std::to_string(triangles) + " world-space triangles, more than the limit of " +
                  std::to_string(kMaxSceneTriangles));
    if (vertices > kMaxSceneVertices)
        root.fail("the scene has " + std::to_string(vertices) + " world-space vertices, more than the limit of " +
                  std::to_string(kMaxSceneVertices));
}

Scene readScene(const JsonField& root, const std::string& directory, const std::string& name) {
    const JsonObject object =
        root.object({"description", "meshes", "materials", "instances", "models", "volumes", "lights", "camera",
                     "environment", "flythrough"});
    if (const auto description = object.optional("description")) description->string();   // for readers only
    Scene scene;
    scene.name = name;
    SceneNames names;
    readMeshes(object["meshes"], directory, scene, names);
    for (const JsonField& material : object["materials"].elements()) readMaterial(material, directory, scene, names);
    for (const JsonField& instance : object["instances"].elements()) readInstance(instance, names, scene);
    checkTextureUvs(object["instances"], scene);
    if (const auto models = object.optional("models"))
        for (const JsonField& model : models->elements()) readModel(model, directory, names, scene);
    if (const auto volumes = object.optional("volumes")) {
        uint64_t voxels = 0;
        for (const JsonField& volume : volumes->elements()) scene.volumes.push_back(readVolume(volume, voxels));
    }
    const std::vector<JsonField> lights = object["lights"].elements();
    if (lights.size() > kMaxSceneLights)
        object["lights"].fail("has " + std::to_string(lights.size()) + " lights, more than the limit of " +
                              std::to_string(kMaxSceneLights));
    for (const JsonField& light : lights) scene.lights.push_back(readLight(light, directory));
    scene.camera = readCamera(object["camera"]);
    if (const auto flythrough = object.optional("flythrough"))
        scene.flythrough = readCameraPath(*flythrough, scene, names.instanceParts);
    if (const auto environment = object.optional("environment")) scene.environment = readEnvironment(*environment, directory);
    // Something must light the scene: a light, or an environment map (the environment
    // techniques need no other light; the shadow techniques then say they have none).
    if (scene.lights.empty() && scene.environment.map.empty())
        object["lights"].fail("needs at least one light, or an environment map (environment.map)");
    checkSize(root, scene);
    return scene;
}

std::string joinedNames(const std::vector<std::string>& names) {
    std::string joined;
    for (const std::string& name : names) joined += (joined.empty() ? "" : ", ") + name;
    return joined;
}

std::string scenePath(const std::string& nameOrPath, const std::string& sceneDir) {
    if (looksLikePath(nameOrPath)) return nameOrPath;
    const fs::path path = fs::path(sceneDir) / (nameOrPath + ".json");
    if (!fs::is_regular_file(path))
        throw SceneError("unknown scene " + inQuotes(nameOrPath) + " (built-in scenes: " + joinedNames(sceneNamesIn(sceneDir)) +
                         "; a scene file path must end in .json, .gltf or .glb or contain a '/')");
    return path.string();
}

}  // namespace

bool looksLikePath(const std::string& nameOrPath) {
    return nameOrPath.find('/') != std::string::npos || fs::path(nameOrPath).extension() == ".json" ||
           isGltfPath(nameOrPath);
}

void checkViewFrame(const JsonObject& object, const Camera& camera) {
    if (const auto problem = viewFrameFieldProblem(camera))
        (object.has(problem->field) ? object[problem->field] : object.field()).fail(problem->problem);
}

std::string findBuiltinDataDir(const std::string& compiledDir) {
    // SHADOWLAB_DATA_DIR_FROM_BIN: the installed data folder relative to the installed
    // executables (scenes/CMakeLists.txt), "../share/shadowlab" by default.
    std::error_code error;
    const fs::path executable = fs::read_symlink("/proc/self/exe", error);
    if (!error) {
        const fs::path installed = (executable.parent_path() / SHADOWLAB_DATA_DIR_FROM_BIN).lexically_normal();
        if (fs::is_directory(installed / "scenes", error)) return installed.string();
    }
    return compiledDir;
}

std::string findBuiltinSceneDir(const std::string& compiledDataDir) {
    const char* override = std::getenv("SHADOWLAB_SCENE_DIR");
    if (override && *override) return override;
    return (fs::path(findBuiltinDataDir(compiledDataDir)) / "scenes").string();
}

std::vector<std::string> sceneNamesIn(const std::string& sceneDir) {
    std::vector<std::string> names;
    std::error_code error;
    for (const fs::directory_entry& entry : fs::directory_iterator(sceneDir, error)) {
        if (entry.is_regular_file() && entry.path().extension() == ".json")
            names.push_back(entry.path().stem().string());
    }
    std::ranges::sort(names);
    return names;
}

Scene parseScene(const std::string& text, const std::string& path) {
    const nlohmann::json document = parseJson(text, path);
    const std::string directory = fs::path(path).parent_path().string();
    return readScene(JsonField(document, path, ""), directory, fs::path(path).stem().string());
}

Scene loadScene(const std::string& nameOrPath, const std::string& sceneDir) {
    const std::string path = scenePath(nameOrPath, sceneDir);
    if (isGltfPath(path)) return loadGltfScene(path);
    return parseScene(readWholeFile(path), path);
}

}  // namespace shadowlab
