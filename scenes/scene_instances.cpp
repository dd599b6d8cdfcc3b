// The "instances" array of a scene file. An instance's worldFromObject is
//   Repeat * Transform * Fit
// Fit normalises the mesh in its own space (height, lowest point), Transform places it
// (translate/rotate/scale or a matrix), Repeat shifts each copy of a lattice.
#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/gtc/matrix_access.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "scenes/error_text.h"
#include "scenes/instance_transform.h"
#include "scenes/scene_file_parts.h"
#include "scenes/scene_limits.h"

namespace shadowlab {
namespace {

constexpr Interval kRepeatCount{1.0, 1024.0, false, false};

uint32_t indexOfName(const JsonField& field, const std::vector<std::string>& names, const char* kind) {
    const std::string name = field.string();
    const auto found = std::ranges::find(names, name);
    if (found == names.end()) field.fail(std::string("no ") + kind + " is named " + inQuotes(name));
    return uint32_t(found - names.begin());
}

// Uniform scale by height / (mesh height) about the object origin; with "ground", the
// mesh is first moved so its lowest point is at y = 0. Both use object-space y only.
glm::mat4 readFit(const JsonField& field, const Mesh& mesh) {
    const JsonObject object = field.object({"height", "ground"});
    if (mesh.positions.empty()) field.fail("the mesh has no vertices to fit");
    float minY = std::numeric_limits<float>::max(), maxY = std::numeric_limits<float>::lowest();
    for (const glm::vec3& p : mesh.positions) {
        minY = std::min(minY, p.y);
        maxY = std::max(maxY, p.y);
    }
    float scale = 1.0f;
    if (const auto height = object.optional("height")) {
        const float wanted = height->number(kPositive);
        if (!(maxY > minY)) height->fail("the mesh has no extent in y to scale");
        scale = float(double(wanted) / (double(maxY) - double(minY)));
    }
    const float bottom = object.optional("ground") && object["ground"].boolean() ? minY : 0.0f;
    glm::mat4 fit(scale);
    fit[3] = glm::vec4(0.0f, -(scale * bottom), 0.0f, 1.0f);   // the lowest vertex maps to exactly 0
    return fit;
}

// "matrix": 16 numbers, row-major as written on paper; glm stores columns.
glm::mat4 readMatrix(const JsonField& field) {
    const std::vector<JsonField> values = field.elements(16);
    glm::mat4 matrix;
    for (int row = 0; row < 4; ++row)
        for (int column = 0; column < 4; ++column) matrix[column][row] = values[size_t(row * 4 + column)].number();
    if (glm::row(matrix, 3) != glm::vec4(0.0f, 0.0f, 0.0f, 1.0f))
        field.fail("the last row must be 0 0 0 1 (an affine transform)");
    // Zero flattens the mesh; negative mirrors it, which turns front faces into back faces.
    if (!(glm::determinant(glm::mat3(matrix)) > 0.0f))
        field.fail("the upper-left 3x3 must have a positive determinant");
    return matrix;
}

// Copy (i, j, k) of the lattice is shifted by (i, j, k) * offset in world space; copies
// are listed with i varying fastest.
// The copies are counted before they are made (1024^3 of them would exhaust memory).
std::vector<glm::vec3> readRepeat(const JsonField& field, size_t instancesBefore) {
    const JsonObject object = field.object({"count", "offset"});
    const std::vector<JsonField> count = object["count"].elements(3);
    const glm::ivec3 n(count[0].integer(kRepeatCount), count[1].integer(kRepeatCount), count[2].integer(kRepeatCount));
    const uint64_t copies = uint64_t(n.x) * uint64_t(n.y) * uint64_t(n.z);
    if (instancesBefore + copies > kMaxInstances)
        object["count"].fail("makes " + std::to_string(copies) + " copies; a scene holds at most " +
                             std::to_string(kMaxInstances) + " instances");
    const glm::vec3 offset = object["offset"].vec3(kCoordinate);
    std::vector<glm::vec3> shifts;
    for (int k = 0; k < n.z; ++k)
        for (int j = 0; j < n.y; ++j)
            for (int i = 0; i < n.x; ++i) shifts.push_back(glm::vec3(i, j, k) * offset);
    return shifts;
}

}  // namespace

InstancePose readPose(const JsonObject& object) {
    InstancePose pose;
    if (const auto field = object.optional("translate")) pose.translate = field->vec3(kCoordinate);
    if (const auto field = object.optional("rotate")) pose.rotateDeg = field->vec3();
    if (const auto field = object.optional("scale"))
        pose.scale = field->raw().is_number() ? glm::vec3(field->number(kPositive)) : field->vec3(kPositive);
    return pose;
}

// Every vertex must land within the world's bound (scene_limits.h, kMaxCoordinate) as
// flatten() places it (worldPosition): a translation of 3e38 with a scale of 2e38 would
// overflow, and coordinates near 2e18 abort Embree.
void checkInWorld(const JsonField& field, const MeshInstance& instance, const Mesh& mesh) {
    for (size_t k = 0; k < mesh.positions.size(); ++k) {
        if (withinWorld(worldPosition(instance, mesh.positions[k]))) continue;
        field.fail("instance " + inQuotes(instance.name) + ": vertex " + std::to_string(k) + " lands outside the world (every coordinate " +
                   kCoordinate.describe() + " metres)");
    }
}

glm::mat4 readTransform(const JsonObject& object) {
    if (!object.has("matrix")) return translateRotateScale(readPose(object));
    if (object.has("translate") || object.has("rotate") || object.has("scale"))
        object["matrix"].fail("cannot be combined with translate, rotate or scale");
    return readMatrix(object["matrix"]);
}

void readInstance(const JsonField& field, SceneNames& names, Scene& scene) {
    const JsonObject object = field.object(
        {"name", "mesh", "material", "translate", "rotate", "scale", "matrix", "fit", "repeat"});
    MeshInstance instance;
    instance.mesh = indexOfName(object["mesh"], names.meshes, "mesh");
    instance.material = indexOfName(object["material"], names.materials, "material");
    instance.name = object.has("name") ? object["name"].string() : names.meshes[instance.mesh];
    const auto fitField = object.optional("fit");
    const glm::mat4 fit = fitField ? readFit(*fitField, scene.meshes[instance.mesh]) : glm::mat4(1.0f);
    instance.worldFromObject = readTransform(object) * fit;
    const auto repeat = object.optional("repeat");
    if (!repeat) {
        if (scene.instances.size() >= kMaxInstances)
            field.fail("a scene holds at most " + std::to_string(kMaxInstances) + " instances");
        checkInWorld(field, instance, scene.meshes[instance.mesh]);
        names.instanceParts.push_back({uint32_t(scene.instances.size()), std::nullopt, fit});
        scene.instances.push_back(instance);
        return;
    }
    const std::vector<glm::vec3> shifts = readRepeat(*repeat, scene.instances.size());
    for (size_t copy = 0; copy < shifts.size(); ++copy) {
        MeshInstance shifted = instance;
        shifted.name = instance.name + "[" + std::to_string(copy) + "]";
        shifted.worldFromObject = glm::translate(glm::mat4(1.0f), shifts[copy]) * instance.worldFromObject;
        checkInWorld(field, shifted, scene.meshes[instance.mesh]);
        names.instanceParts.push_back({uint32_t(scene.instances.size()), shifts[copy], fit});
        scene.instances.push_back(shifted);
    }
}

}  // namespace shadowlab
