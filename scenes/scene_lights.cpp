// The "lights" array of a scene file (conventions.md, "Lights"; scene.h, Light).
#include <array>
#include <cmath>
#include <filesystem>

#include "scenes/light_cookie.h"
#include "scenes/scene_error.h"
#include "scenes/scene_file_parts.h"

namespace shadowlab {
namespace {

constexpr std::array<std::pair<std::string_view, LightType>, 5> kLightTypes{{
    {"point", LightType::Point},
    {"spot", LightType::Spot},
    {"directional", LightType::Directional},
    {"disk", LightType::Disk},
    {"rectangle", LightType::Rectangle}}};

// A spot's half-angle: beyond 90 degrees it would no longer be a cone in front of it.
constexpr Interval kConeAngleDeg{0.0, 90.0, true, false};

// A sun's angular diameter: below 180 degrees its disk on the sky is a cap smaller than a
// hemisphere, whose directions the soft reference samples (shading/light_sampling.h, sunCap).
constexpr Interval kAngularDiameterDeg{0.0, 180.0, false, true};

// Two vectors count as perpendicular when the cosine of their angle is below this; it
// allows for the rounding of hand-typed decimals such as 0.7071.
constexpr double kPerpendicularCosine = 1e-4;

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

// Normalised in double: a tiny but non-zero vector would underflow in float.
glm::vec3 unitDirection(const JsonField& field) {
    const glm::dvec3 v(field.vec3());
    const double length = glm::length(v);
    if (!(length > 0.0)) field.fail("must not be the zero vector");
    return glm::vec3(v / length);
}

void readRectangle(const JsonObject& object, Light& light) {
    light.halfEdgeU = object["halfEdgeU"].vec3(kCoordinate);
    light.halfEdgeV = object["halfEdgeV"].vec3(kCoordinate);
    const glm::dvec3 u(light.halfEdgeU), v(light.halfEdgeV);
    if (!(glm::length(glm::cross(u, v)) > 0.0))
        object["halfEdgeV"].fail("the rectangle has zero area (a half-edge is zero or they are parallel)");
    if (std::abs(glm::dot(u, v)) > kPerpendicularCosine * glm::length(u) * glm::length(v))
        object["halfEdgeV"].fail("must be perpendicular to halfEdgeU");
}

// A point or spot light's range and a spot's inner cone, as KHR_lights_punctual's (shading/lights.h,
// conventions.md "Lights"); absent: unbounded, and a hard cone.
void readPunctualFalloff(const JsonObject& object, Light& light) {
    if (const auto range = object.optional("range")) light.range = float(range->number(kPositive));
    if (light.type != LightType::Spot) return;
    if (const auto inner = object.optional("innerConeAngle"))
        light.innerConeAngleDeg = float(inner->number(Interval{0.0, double(light.coneAngleDeg), false, true}));
}

void readShape(const JsonObject& object, Light& light) {
    switch (light.type) {
        case LightType::Point: readPunctualFalloff(object, light); break;
        case LightType::Spot:
            light.direction = unitDirection(object["direction"]);
            light.coneAngleDeg = object["coneAngle"].number(kConeAngleDeg);
            readPunctualFalloff(object, light);
            break;
        case LightType::Directional:
            light.direction = unitDirection(object["direction"]);
            if (const auto angle = object.optional("angularDiameter"))
                light.angularDiameterDeg = float(angle->number(kAngularDiameterDeg));
            break;
        case LightType::Disk:
            light.direction = unitDirection(object["normal"]);
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
    if (glm::any(glm::isinf(light.intensity))) object["power"].fail("color * power overflows float");
    if (const auto cookie = object.optional("cookie")) light.cookie = readCookie(*cookie, directory);
    return light;
}

}  // namespace shadowlab
