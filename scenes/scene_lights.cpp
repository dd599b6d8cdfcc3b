// The "lights" array of a scene file (conventions.md, "Lights"; scene.h, Light).
#include <array>
#include <filesystem>

#include "scenes/light_cookie.h"
#include "scenes/scene_error.h"
#include "scenes/scene_file_parts.h"

namespace shadowlab {
namespace {

std::vector<std::string_view> keysFor(LightType type) {
    switch (type) {
        case LightType::Point: return {"type", "position", "color", "power", "range"};
        case LightType::Spot:
            return {"type", "position", "direction", "coneAngle", "innerConeAngle", "range", "color", "power", "cookie"};
        case LightType::Directional: return {"type", "direction", "angularDiameter", "color", "power"};
        case LightType::Disk: return {"type", "position", "normal", "radius", "color", "power"};
        case LightType::Rectangle: return {"type", "position", "halfEdgeU", "halfEdgeV", "color", "power"};
    }
    return {};   // unreachable: every enumerator is handled above
}

// A zero direction is left for lightProblem to report.
glm::vec3 directionOf(const JsonField& field) {
    const glm::vec3 v = field.vec3();
    return unitDirection(v).value_or(v);
}

// Its half-edges; lightProblem checks that they span a rectangle.
void readRectangle(const JsonObject& object, Light& light) {
    light.halfEdgeU = object["halfEdgeU"].vec3(kCoordinate);
    light.halfEdgeV = object["halfEdgeV"].vec3(kCoordinate);
}

// A point or spot light's range and a spot's inner cone, as KHR_lights_punctual's (shading/lights.h,
// conventions.md "Lights"); absent: unbounded, and a hard cone. lightProblem checks the inner
// cone against the cone.
void readPunctualFalloff(const JsonObject& object, Light& light) {
    if (const auto range = object.optional("range")) light.range = float(range->number(kPositive));
    if (light.type != LightType::Spot) return;
    if (const auto inner = object.optional("innerConeAngle")) light.innerConeAngleDeg = inner->number();
}

void readShape(const JsonObject& object, Light& light) {
    switch (light.type) {
        case LightType::Point: readPunctualFalloff(object, light); break;
        case LightType::Spot:
            light.direction = directionOf(object["direction"]);
            light.coneAngleDeg = object["coneAngle"].number(kConeAngleDeg);
            readPunctualFalloff(object, light);
            break;
        case LightType::Directional:
            light.direction = directionOf(object["direction"]);
            if (const auto angle = object.optional("angularDiameter"))
                light.angularDiameterDeg = float(angle->number(kAngularDiameterDeg));
            break;
        case LightType::Disk:
            light.direction = directionOf(object["normal"]);
            light.radius = object["radius"].number(kPositive);
            break;
        case LightType::Rectangle: readRectangle(object, light); break;
    }
}

// A spot's cookie, its path relative to the scene file's folder.
std::shared_ptr<const LightCookie> readCookie(const JsonField& field, const std::string& directory) {
    try {
        const std::filesystem::path path = std::filesystem::path(directory) / field.string();
        return std::make_shared<const LightCookie>(readLightCookie(path.string()));
    } catch (const SceneError& error) {
        field.fail(error);
    }
}

}  // namespace

Light readLight(const JsonField& field, const std::string& directory) {
    const JsonObject object = field.object();
    Light light;
    light.type = object["type"].choice(kLightTypes);
    if (light.type != LightType::Spot && object.has("cookie")) {
        object["cookie"].fail("is projected through a spot light's cone: only a spot light may have one");
    }
    object.allowOnly(keysFor(light.type));
    if (light.type != LightType::Directional) light.position = object["position"].vec3(kCoordinate);
    readShape(object, light);
    const glm::vec3 color = object.has("color") ? object["color"].vec3(kNonNegative) : glm::vec3(1.0f);
    light.intensity = color * object["power"].number(kNonNegative);
    // The rules that join fields (view_rules.h): a rectangle's edges, a spot's inner cone, the
    // product color * power; the rest are checked above where they are read, with the value given.
    if (const auto problem = lightProblem(light)) object[problem->field].fail(problem->problem);
    if (const auto cookie = object.optional("cookie")) light.cookie = readCookie(*cookie, directory);
    return light;
}

}  // namespace shadowlab
