// The "meshes" array of a scene file: procedural meshes and OBJ/PLY files.
#include <algorithm>
#include <array>
#include <cctype>
#include <filesystem>

#include "scenes/error_text.h"
#include "scenes/obj_reader.h"
#include "scenes/ply_reader.h"
#include "scenes/procedural.h"
#include "scenes/procedural_casters.h"
#include "scenes/scene_error.h"
#include "scenes/scene_file_parts.h"
#include "scenes/scene_limits.h"

namespace shadowlab {
namespace {

// Caps divisions, slices and stacks so that every procedural mesh's vertex count
// (at most 16385^2) fits the 32-bit indices of Mesh::triangles.
constexpr Interval kDivisions{1.0, 16384.0, false, false};
constexpr Interval kSlices{3.0, 16384.0, false, false};
constexpr Interval kStacks{2.0, 16384.0, false, false};

enum class Procedural { Grid, UvSphere, Box, Hair };
constexpr std::array<std::pair<std::string_view, Procedural>, 4> kProcedurals{{
    {"grid", Procedural::Grid}, {"uv-sphere", Procedural::UvSphere}, {"box", Procedural::Box},
    {"hair", Procedural::Hair}}};
constexpr Interval kStrands{1.0, 1048576.0, false, false};
constexpr Interval kSegments{1.0, 1024.0, false, false};

// A procedural mesh's triangles are counted before it is made: 16384 x 16384 divisions
// would be half a billion triangles from a line of JSON.
void checkProceduralSize(const JsonField& field, uint64_t triangles) {
    if (triangles > kMaxSceneTriangles)
        field.fail("makes " + std::to_string(triangles) + " triangles, more than a scene may hold (" +
                   std::to_string(kMaxSceneTriangles) + ")");
}

Mesh readGrid(const JsonObject& object) {
    object.allowOnly({"name", "procedural", "size", "divisions"});
    const std::vector<JsonField> size = object["size"].elements(2);
    const std::vector<JsonField> divisions = object["divisions"].elements(2);
    const glm::ivec2 n(divisions[0].integer(kDivisions), divisions[1].integer(kDivisions));
    checkProceduralSize(object["divisions"], gridTriangleCount(n));
    return makeGrid({size[0].number(kPositive), size[1].number(kPositive)}, n);
}

Mesh readUvSphere(const JsonObject& object) {
    object.allowOnly({"name", "procedural", "radius", "slices", "stacks"});
    const int slices = object["slices"].integer(kSlices), stacks = object["stacks"].integer(kStacks);
    checkProceduralSize(object["stacks"], uvSphereTriangleCount(slices, stacks));
    return makeUvSphere(object["radius"].number(kPositive), slices, stacks);
}

Mesh readBox(const JsonObject& object) {
    object.allowOnly({"name", "procedural", "min", "max"});
    const glm::vec3 min = object["min"].vec3(), max = object["max"].vec3();
    if (!glm::all(glm::lessThan(min, max)))
        object["max"].fail("must be greater than min in x, y and z (a flat box has no inside)");
    return makeBox(min, max);
}

Mesh readHair(const JsonObject& object) {
    object.allowOnly({"name", "procedural", "size", "strands", "width", "segments", "seed"});
    HairPatchSettings settings;
    settings.size = object["size"].vec3(kPositive);
    settings.strands = object["strands"].integer(kStrands);
    settings.width = object["width"].number(kPositive);
    if (const auto segments = object.optional("segments")) settings.segments = segments->integer(kSegments);
    if (const auto seed = object.optional("seed")) settings.seed = uint64_t(seed->integer(kSeed));
    checkProceduralSize(object["strands"], hairPatchTriangleCount(settings.strands, settings.segments));
    return makeHairPatch(settings);
}

Mesh readProcedural(const JsonObject& object) {
    switch (object["procedural"].choice(kProcedurals)) {
        case Procedural::Grid: return readGrid(object);
        case Procedural::UvSphere: return readUvSphere(object);
        case Procedural::Box: return readBox(object);
        case Procedural::Hair: return readHair(object);
    }
    return {};   // unreachable: every enumerator is handled above
}

std::string lowercaseExtension(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return extension;
}

// Reader errors already name the mesh file; prefixing the field tells which entry of
// the scene file pointed at it.
Mesh readMeshFile(const JsonObject& object, const std::string& directory) {
    object.allowOnly({"name", "file"});
    const JsonField field = object["file"];
    const std::string path = (std::filesystem::path(directory) / field.string()).string();
    const std::string extension = lowercaseExtension(path);
    if (extension != ".obj" && extension != ".ply")
        field.fail("unknown mesh format " + inQuotes(extension) + " (allowed: .obj, .ply)");
    try {
        return extension == ".obj" ? readObj(path) : readPly(path);
    } catch (const SceneError& error) {
        field.fail(error);
    }
}

}  // namespace

Mesh readMesh(const JsonObject& object, const std::string& directory) {
    if (object.has("file") == object.has("procedural"))
        object.field().fail("needs exactly one of \"file\" and \"procedural\"");
    return object.has("file") ? readMeshFile(object, directory) : readProcedural(object);
}

void readMeshes(const JsonField& field, const std::string& directory, Scene& scene, SceneNames& names) {
    for (const JsonField& entry : field.elements()) {
        const JsonObject object = entry.object();
        const JsonField nameField = object["name"];
        const std::string name = nameField.string();
        if (std::ranges::find(names.meshes, name) != names.meshes.end())
            nameField.fail("another mesh is already named " + inQuotes(name));
        scene.meshes.push_back(readMesh(object, directory));
        names.meshes.push_back(name);
    }
}

}  // namespace shadowlab
