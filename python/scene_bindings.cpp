// Scene: a value, the library's Scene as a scene file or a built-in scene describes it, loaded
// from a name, a path or a dict (load_scene() in the package's __init__.py, which finds the
// built-in scene directory), with the command's overrides of its camera and lights.
#include <optional>
#include <string>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "frame/render.h"
#include "python/bindings.h"
#include "python/conversions.h"
#include "python/view_values.h"
#include "scenes/scene.h"
#include "scenes/scene_file.h"

namespace py = pybind11;

namespace shadowlab::python {
namespace {

// Scene.apply_overrides: the command's --light, --width, --height, --eye, --target, --fovy,
// --light-pos and --light-radius, checked as the command checks them.
void applyOverridesTo(Scene& scene, std::optional<int> light, std::optional<int> width, std::optional<int> height,
                      std::optional<glm::vec3> eye, std::optional<glm::vec3> target, std::optional<float> fovyDeg,
                      std::optional<glm::vec3> lightPosition, std::optional<float> lightRadius) {
    applyOverrides(scene, {.light = light, .width = width, .height = height, .eye = eye, .target = target,
                           .lightPosition = lightPosition, .fovyDeg = fovyDeg, .lightRadius = lightRadius});
}

size_t triangleCount(const Scene& scene) {
    size_t count = 0;
    for (const MeshInstance& instance : scene.instances) count += scene.meshes[instance.mesh].triangles.size();
    return count;
}

}  // namespace

void bindScene(py::module_& m) {
    py::class_<Scene>(m, "Scene",
                      "A scene (a value: the library's Scene, copied where it is passed). Make one with "
                      "load_scene(); prepare() makes it ready for frames.")
        .def_readwrite("name", &Scene::name, "its name: a file's stem or a built-in scene's name")
        .def_property(
            "camera", [](const Scene& s) { return s.camera; }, [](Scene& s, const Camera& camera) { s.camera = camera; },
            "its Camera (a value); assign one to change it: scene.camera = scene.camera.replace(width=64)")
        .def_property(
            "lights", [](const Scene& s) { return s.lights; },
            [](Scene& s, std::vector<Light> lights) {
                requireValid(lights);
                s.lights = std::move(lights);
            },
            "its Lights (values), a list; assign a list to change them (their number too, at most 16): "
            "scene.lights = [l.replace(radius=0.5) for l in scene.lights]")
        .def_property_readonly("instance_names", &instanceNames, "the names of its mesh instances, in order")
        .def_property_readonly("triangle_count", &triangleCount, "triangles over every instance")
        .def_property_readonly(
            "instance_transforms",
            [](const Scene& s) {
                py::dict transforms;
                for (const MeshInstance& instance : s.instances)
                    transforms[py::str(instance.name)] = matrixArray(instance.worldFromObject);
                return transforms;
            },
            "each instance's world-from-object matrix by name, (4, 4) float32 copies acting on column vectors")
        .def_readonly("notes", &Scene::notes, "what the loader supplied or left out, one line each (glTF files)")
        .def("apply_overrides", &applyOverridesTo, py::kw_only(), py::arg("light") = py::none(),
             py::arg("width") = py::none(), py::arg("height") = py::none(), py::arg("eye") = py::none(),
             py::arg("target") = py::none(), py::arg("fovy_deg") = py::none(), py::arg("light_position") = py::none(),
             py::arg("light_radius") = py::none(),
             "Changes the scene as the command's options do (--light N keeps that light alone, --width, --height, "
             "--eye, --target, --fovy, --light-pos and --light-radius act on the first light), with their checks: "
             "ValueError with the command's message, and then the scene may be half changed.")
        .def("__copy__", [](const Scene& s) { return s; })
        .def("__deepcopy__", [](const Scene& s, const py::dict&) { return s; })
        .def("__repr__", [](const Scene& s) {
            return "<Scene " + s.name + ": " + std::to_string(s.instances.size()) + " instances, " +
                   std::to_string(s.lights.size()) + " lights>";
        });

    m.def("_load_scene", &sceneFromSource, py::arg("source"), py::arg("base_dir"), py::arg("scene_dir"),
          "load_scene() against the built-in scene directory scene_dir");
    m.def("_looks_like_path", &looksLikePath, py::arg("name_or_path"),
          "whether load_scene() reads a str as a path (it ends in .json, .gltf or .glb or has a '/') or as a name");
    m.def("_scene_names", &sceneNamesIn, py::arg("scene_dir"), "the stems of the scene files in scene_dir, sorted");
    m.attr("_compiled_data_dir") = SHADOWLAB_DATA_DIR;
    m.attr("_data_dir_from_package") = SHADOWLAB_DATA_DIR_FROM_PACKAGE;
}

}  // namespace shadowlab::python
