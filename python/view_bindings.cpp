// Camera and Light, the parts of a scene a user moves between frames: immutable values
// (value_type.h) with their fields named as the scene format names them
// (docs/scene-format.md), in snake_case, and checked by the scene format's rules
// (scenes/view_rules.h) wherever one is made.
#include <memory>
#include <string>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "python/bindings.h"
#include "python/conversions.h"
#include "python/value_type.h"
#include "python/view_values.h"

namespace py = pybind11;

namespace shadowlab::python {
namespace {

// The scene format's names of the light types (view_rules.h, kLightTypes), both ways.
LightType lightType(const std::string& name) {
    for (const auto& [typeName, type] : kLightTypes)
        if (name == typeName) return type;
    throw std::invalid_argument("unknown light type \"" + name + "\" (point, spot, directional, disk, rectangle)");
}

std::string lightTypeName(LightType type) {
    for (const auto& [typeName, each] : kLightTypes)
        if (each == type) return std::string(typeName);
    return "unknown";   // unreachable: the table names every type
}

std::shared_ptr<const ValueType<Camera>> cameraValueType() {
    static const auto type = std::make_shared<const ValueType<Camera>>(ValueType<Camera>{
        .name = "Camera",
        .fields = {memberField("eye", "eye", &Camera::eye, "position, world space (m)"),
                   memberField("target", "target", &Camera::target, "the point it looks at"),
                   memberField("up", "up", &Camera::up, "the direction that is up in the image"),
                   memberField("fovy_deg", "fovy", &Camera::fovyDeg, "vertical field of view, degrees in (0, 180)"),
                   memberField("width", "width", &Camera::width, "image width, pixels (1..8192)"),
                   memberField("height", "height", &Camera::height, "image height, pixels (1..8192)"),
                   memberField("near", "near", &Camera::zNear, "near plane distance (m), > 0"),
                   memberField("far", "far", &Camera::zFar, "far plane distance (m), beyond near")},
        .problem = cameraProblem});
    return type;
}

// A direction given is normalised, as a scene file's is (view_rules.h, unitDirection).
ValueField<Light> directionField() {
    return {"direction", "direction",
            "a unit vector, normalised when given. spot: its axis; directional: towards the light; disk: the "
            "emitting side's normal",
            [](const Light& l) { return py::cast(l.direction); },
            [](Light& l, py::handle given) {
                const glm::vec3 v = given.cast<glm::vec3>();
                l.direction = unitDirection(v).value_or(v);
            }};
}

std::shared_ptr<const ValueType<Light>> lightValueType() {
    static const auto type = std::make_shared<const ValueType<Light>>(ValueType<Light>{
        .name = "Light",
        .fields = {{"type", "type", "\"point\", \"spot\", \"directional\", \"disk\" or \"rectangle\"",
                    [](const Light& l) { return py::cast(lightTypeName(l.type)); },
                    [](Light& l, py::handle given) { l.type = lightType(given.cast<std::string>()); }},
                   memberField("position", "position", &Light::position,
                               "point, spot; the centre of a disk or rectangle; within the world's limits"),
                   directionField(),
                   memberField("cone_angle", "coneAngle", &Light::coneAngleDeg,
                               "spot: the cone's half-angle, degrees in (0, 90]"),
                   memberField("inner_cone_angle", "innerConeAngle", &Light::innerConeAngleDeg,
                               "spot: where the falloff to the cone's edge begins, degrees in [0, cone_angle); "
                               "None: a hard cone"),
                   memberField("range", "range", &Light::range,
                               "point, spot: the distance beyond which no light arrives, >= 0; 0: unbounded"),
                   memberField("radius", "radius", &Light::radius, "disk: its radius (m), > 0"),
                   memberField("half_edge_u", "halfEdgeU", &Light::halfEdgeU, "rectangle: half of one edge, from its centre"),
                   memberField("half_edge_v", "halfEdgeV", &Light::halfEdgeV,
                               "rectangle: half of the other edge, perpendicular to u"),
                   memberField("angular_diameter", "angularDiameter", &Light::angularDiameterDeg,
                               "directional: the sun's angular diameter, degrees in [0, 180); 0: a point-like sun"),
                   memberField("intensity", "power", &Light::intensity,
                               "RGB, each >= 0: the scene format's color times power")},
        .problem = lightProblem,
        .keyAliases = {{"normal", "direction"}},
        .sameRest = [](const Light& a, const Light& b) { return a.cookie == b.cookie; },
        .pickles = [](const Light& l) { return l.cookie == nullptr; }});
    return type;
}

void bindCamera(py::module_& m) {
    py::class_<Camera> camera(m, "Camera",
                              "A scene's camera: an immutable value, as a frozen dataclass. Camera(width=64, ...) "
                              "makes one from the library's default camera; camera.replace(width=64) gives a "
                              "changed copy. Checked by the scene format's rules wherever one is made (ValueError).");
    bindValueType(camera, cameraValueType(),
                  "Camera(*, eye, target, up, fovy_deg, width, height, near, far): the library's default camera "
                  "with the fields given, checked (ValueError).");
}

void bindLight(py::module_& m) {
    py::class_<Light> light(m, "Light",
                            "A light (conventions.md, \"Lights\"): an immutable value, as a frozen dataclass; "
                            "light.replace(radius=0.5) gives a changed copy. intensity is the scene format's color "
                            "times power: W/sr for point and spot, W/m^2 for directional, W/(m^2 sr) for disk and "
                            "rectangle. Checked by the scene format's rules for its type wherever one is made "
                            "(ValueError); it pickles unless it has a cookie.");
    bindValueType(light, lightValueType(),
                  "Light(*, type, position, direction, cone_angle, inner_cone_angle, range, radius, half_edge_u, "
                  "half_edge_v, angular_diameter, intensity): a point light at the origin of intensity 1 with the "
                  "fields given, checked (ValueError).");
    light.def_property_readonly(
        "has_cookie", [](const Light& l) { return l.cookie != nullptr; }, "spot: whether it projects a cookie");
}

}  // namespace

void requireValid(const Camera& camera) { requireValid(*cameraValueType(), camera); }

void requireValid(const std::vector<Light>& lights) {
    if (lights.size() > kMaxSceneLights)
        throw std::invalid_argument(std::to_string(lights.size()) + " lights, more than the limit of " +
                                    std::to_string(kMaxSceneLights));
    for (const Light& light : lights) requireValid(*lightValueType(), light);
}

void bindView(py::module_& m) {
    bindCamera(m);
    bindLight(m);
}

}  // namespace shadowlab::python
