// The "models" array of a scene file (docs/scene-format.md, "models"): a glTF file placed
// whole, its meshes with their node transforms and its materials (cut-outs included),
// unless the entry names one of the scene's materials for all of them. Its cameras and
// lights are not read: the scene file has its own.
#include <algorithm>
#include <filesystem>

#include "scenes/error_text.h"
#include "scenes/gltf_scene.h"
#include "scenes/scene_error.h"
#include "scenes/scene_file_parts.h"

namespace shadowlab {

void readModel(const JsonField& field, const std::string& directory, const SceneNames& names, Scene& scene) {
    const JsonObject object = field.object({"name", "file", "material", "translate", "rotate", "scale", "matrix"});
    const std::string name = object["name"].string();
    const JsonField fileField = object["file"];
    const std::string path = (std::filesystem::path(directory) / fileField.string()).string();
    if (!isGltfPath(path)) fileField.fail("a model is a glTF file (.gltf or .glb)");
    std::optional<uint32_t> material;
    if (const auto materialField = object.optional("material")) {
        const std::string materialName = materialField->string();
        const auto found = std::ranges::find(names.materials, materialName);
        if (found == names.materials.end()) materialField->fail("no material is named " + inQuotes(materialName));
        material = uint32_t(found - names.materials.begin());
    }
    const glm::mat4 placement = readTransform(object);
    try {
        appendGltfModel(readGltfModel(path), placement, material, name, scene);
    } catch (const SceneError& error) {
        fileField.fail(error);
    }
}

}  // namespace shadowlab
