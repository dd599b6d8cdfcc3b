#include "scenes/gltf/gltf_lights.h"

#include <cmath>
#include <numbers>

#include "scenes/scene_limits.h"

namespace shadowlab {
namespace {

// The light a node names in extensions.KHR_lights_punctual.light, or -1.
int nodeLightIndex(const GltfDocument& document, size_t node) {
    const tinygltf::ExtensionMap& extensions = document.model.nodes[node].extensions;
    const auto found = extensions.find("KHR_lights_punctual");
    if (found == extensions.end()) return -1;
    const tinygltf::Value& light = found->second.Get("light");
    const std::string field = "nodes[" + std::to_string(node) + "].extensions.KHR_lights_punctual.light";
    if (!light.IsInt()) document.fail(field, "must be an integer");
    const int index = light.GetNumberAsInt();
    if (index < 0 || size_t(index) >= document.model.lights.size())
        document.fail(field, "names light " + std::to_string(index) + ", but the file has " +
                                 std::to_string(document.model.lights.size()));
    return index;
}

glm::vec3 unitOrFail(const GltfDocument& document, const glm::dvec3& v, const std::string& field) {
    const double length = glm::length(v);
    if (!(length > 0.0) || !std::isfinite(length)) document.fail(field, "its transform leaves the light no direction");
    return glm::vec3(v / length);
}

double toDegrees(double radians) { return radians * 180.0 / std::numbers::pi; }

void readSpot(const GltfDocument& document, const tinygltf::SpotLight& spot, const std::string& field, Light& light) {
    const double inner = spot.innerConeAngle, outer = spot.outerConeAngle;
    // The extension allows outerConeAngle = pi/2; our spot's cone (and its light view) must
    // stay under a half-space.
    if (!(outer > 0.0 && outer < std::numbers::pi / 2))
        document.fail(field + ".spot.outerConeAngle", "must be in (0, pi/2) here, got " + std::to_string(outer));
    if (!(inner >= 0.0 && inner < outer))
        document.fail(field + ".spot.innerConeAngle", "must be in [0, outerConeAngle), got " + std::to_string(inner));
    light.coneAngleDeg = float(toDegrees(outer));
    light.innerConeAngleDeg = float(toDegrees(inner));
}

}  // namespace

std::optional<Light> readNodeLight(const GltfDocument& document, size_t node, const glm::dmat4& worldFromNode) {
    const int index = nodeLightIndex(document, node);
    if (index < 0) return std::nullopt;
    const tinygltf::Light& source = document.model.lights[size_t(index)];
    const std::string field = "extensions.KHR_lights_punctual.lights[" + std::to_string(index) + "]";
    Light light;
    glm::dvec3 color(1.0);
    if (!source.color.empty()) {
        if (source.color.size() != 3) document.fail(field + ".color", "must be 3 numbers");
        color = glm::dvec3(source.color[0], source.color[1], source.color[2]);
        if (!(glm::all(glm::greaterThanEqual(color, glm::dvec3(0.0))) && glm::all(glm::lessThanEqual(color, glm::dvec3(1.0)))))
            document.fail(field + ".color", "each must be in [0, 1]");
    }
    if (!(source.intensity >= 0.0 && source.intensity < 1e30))
        document.fail(field + ".intensity", "must be a finite number >= 0");
    light.intensity = glm::vec3(color * source.intensity);
    const std::string nodeField = "nodes[" + std::to_string(node) + "]";
    const glm::dvec3 forward(worldFromNode * glm::dvec4(0.0, 0.0, -1.0, 0.0));
    if (source.type == "directional") {
        light.type = LightType::Directional;
        light.direction = -unitOrFail(document, forward, nodeField);   // ours points towards the light
        return light;   // KHR_lights_punctual has no angular size: a point-like sun, angularDiameterDeg 0
    }
    light.position = glm::vec3(worldFromNode[3]);
    if (!(std::abs(light.position.x) <= kMaxCoordinate && std::abs(light.position.y) <= kMaxCoordinate &&
          std::abs(light.position.z) <= kMaxCoordinate))
        document.fail(nodeField, "places its light outside the world (coordinates within 1e6 m)");
    if (!(source.range >= 0.0 && source.range < 1e30))
        document.fail(field + ".range", "must be a finite number > 0 (absent: unbounded)");
    light.range = float(source.range);   // 0: tinygltf's "absent", unbounded
    if (source.type == "point") {
        light.type = LightType::Point;
    } else if (source.type == "spot") {
        light.type = LightType::Spot;
        light.direction = unitOrFail(document, forward, nodeField);
        readSpot(document, source.spot, field, light);
    } else {
        document.fail(field + ".type", "must be directional, point or spot, got " + source.type);
    }
    return light;
}

}  // namespace shadowlab
