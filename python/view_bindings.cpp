// Camera and Light, the parts of a scene a user moves between frames: values with their fields
// named as the scene format names them (docs/scene-format.md), in snake_case.
#include <array>
#include <string>

#include <pybind11/operators.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "python/bindings.h"
#include "python/conversions.h"
#include "scenes/scene.h"

namespace py = pybind11;

namespace shadowlab::python {
namespace {

constexpr std::array<const char*, 5> kLightTypes = {"point", "spot", "directional", "disk", "rectangle"};

LightType lightType(const std::string& name) {
    for (size_t k = 0; k < kLightTypes.size(); ++k)
        if (name == kLightTypes[k]) return LightType(k);
    throw std::invalid_argument("unknown light type \"" + name + "\" (point, spot, directional, disk, rectangle)");
}

void bindCamera(py::module_& m) {
    py::class_<Camera>(m, "Camera", "A scene's camera (a value: copy.copy() gives another). Checked where it is used: "
                                    "prepare(), PreparedScene.camera, Scene.apply_overrides().")
        .def(py::init<>(), "The library's default camera.")
        .def_readwrite("eye", &Camera::eye, "position, world space (m)")
        .def_readwrite("target", &Camera::target, "the point it looks at")
        .def_readwrite("up", &Camera::up, "the direction that is up in the image")
        .def_readwrite("fovy_deg", &Camera::fovyDeg, "vertical field of view, degrees in (0, 180)")
        .def_readwrite("width", &Camera::width, "image width, pixels (1..8192)")
        .def_readwrite("height", &Camera::height, "image height, pixels (1..8192)")
        .def_readwrite("near", &Camera::zNear, "near plane distance (m)")
        .def_readwrite("far", &Camera::zFar, "far plane distance (m)")
        .def("__copy__", [](const Camera& c) { return c; })
        .def("__deepcopy__", [](const Camera& c, const py::dict&) { return c; })
        .def(py::self == py::self)
        .def("__repr__", [](const Camera& c) {
            return "Camera(eye=" + std::string(py::repr(py::cast(c.eye))) + ", target=" +
                   std::string(py::repr(py::cast(c.target))) + ", fovy_deg=" + std::to_string(c.fovyDeg) + ", " +
                   std::to_string(c.width) + " x " + std::to_string(c.height) + ")";
        });
}

void bindLight(py::module_& m) {
    py::class_<Light>(m, "Light", "A light (a value; conventions.md, \"Lights\"). intensity is the scene format's "
                                  "color times power: W/sr for point and spot, W/m^2 for directional, W/(m^2 sr) "
                                  "for disk and rectangle. Fields are not checked when set: a scene file's checks "
                                  "apply to files only.")
        .def(py::init<>(), "A point light at the origin of intensity 1.")
        .def_property(
            "type", [](const Light& l) { return std::string(kLightTypes[size_t(l.type)]); },
            [](Light& l, const std::string& name) { l.type = lightType(name); },
            "\"point\", \"spot\", \"directional\", \"disk\" or \"rectangle\"")
        .def_readwrite("position", &Light::position, "point, spot; the centre of a disk or rectangle")
        .def_readwrite("direction", &Light::direction,
                       "spot: its axis; directional: towards the light; disk: the emitting side's normal")
        .def_readwrite("cone_angle", &Light::coneAngleDeg, "spot: the cone's half-angle, degrees")
        .def_readwrite("inner_cone_angle", &Light::innerConeAngleDeg,
                       "spot: where the falloff to the cone's edge begins, degrees; None: a hard cone")
        .def_readwrite("range", &Light::range, "point, spot: the distance beyond which no light arrives; 0: unbounded")
        .def_readwrite("radius", &Light::radius, "disk: its radius (m)")
        .def_readwrite("half_edge_u", &Light::halfEdgeU, "rectangle: half of one edge, from its centre")
        .def_readwrite("half_edge_v", &Light::halfEdgeV, "rectangle: half of the other edge, perpendicular to u")
        .def_readwrite("angular_diameter", &Light::angularDiameterDeg,
                       "directional: the sun's angular diameter, degrees; 0: a point-like sun")
        .def_readwrite("intensity", &Light::intensity, "RGB: the scene format's color times power")
        .def_property_readonly(
            "has_cookie", [](const Light& l) { return l.cookie != nullptr; }, "spot: whether it projects a cookie")
        .def("__copy__", [](const Light& l) { return l; })
        .def("__deepcopy__", [](const Light& l, const py::dict&) { return l; })
        .def("__repr__", [](const Light& l) {
            return "Light(type=\"" + std::string(kLightTypes[size_t(l.type)]) +
                   "\", position=" + std::string(py::repr(py::cast(l.position))) + ")";
        });
}

}  // namespace

void bindView(py::module_& m) {
    bindCamera(m);
    bindLight(m);
}

}  // namespace shadowlab::python
