// PreparedScene: a scene made ready for frames (scenes/prepared_scene.h), shared by whatever
// renders it. Its camera and lights change between frames without preparing it again, as the
// fly-through moves them (app/measure/flythrough.cpp: PreparedScene::setCamera, setLights).
#include <algorithm>
#include <memory>
#include <mutex>
#include <shared_mutex>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "frame/render.h"
#include "python/bindings.h"
#include "python/conversions.h"
#include "python/handles.h"
#include "python/view_values.h"

namespace py = pybind11;

namespace shadowlab::python {
namespace {

// Placements from {instance: matrix}, an instance by its index or its name (`names`, the
// scene's instances in order).
std::vector<InstancePlacement> placementsOf(const std::vector<std::string>& names, const py::dict& transforms) {
    std::vector<InstancePlacement> placements;
    for (const auto& [key, matrix] : transforms) {
        uint32_t index = 0;
        if (py::isinstance<py::int_>(key) && !py::isinstance<py::bool_>(key)) {
            const long long k = key.cast<long long>();
            if (k < 0 || k >= (long long)names.size())
                throw std::invalid_argument("instance " + std::to_string(k) + " out of range (the scene has " +
                                            std::to_string(names.size()) + ")");
            index = uint32_t(k);
        } else if (py::isinstance<py::str>(key)) {
            const std::string name = key.cast<std::string>();
            const auto found = std::find(names.begin(), names.end(), name);
            if (found == names.end()) throw std::invalid_argument("no instance is named \"" + name + "\"");
            index = uint32_t(found - names.begin());
        } else {
            throw py::type_error("an instance is its index (int) or its name (str)");
        }
        placements.push_back({index, matrixOf(matrix)});
    }
    return placements;
}

std::shared_ptr<PreparedHandle> prepare(Scene scene) {
    // A scene's camera and lights as the scene format's rules have them (view_rules.h): a scene
    // changed in C++ or loaded past them never reaches the renderer.
    requireValid(scene.camera);
    requireValid(scene.lights);
    py::gil_scoped_release release;
    return std::make_shared<PreparedHandle>(std::move(scene));
}

// A change between frames: waits (without the GIL) for the frames rendering to finish.
template <class Change>
void change(PreparedHandle& handle, Change&& apply) {
    py::gil_scoped_release release;
    const std::unique_lock lock(handle.mutex);
    apply(handle.prepared);
}

// A read between frames: waits (without the GIL, so that other Python threads run while a
// change holds the lock) and reads C++ values only.
template <class Read>
auto read(PreparedHandle& handle, Read&& get) {
    py::gil_scoped_release release;
    const std::shared_lock lock(handle.mutex);
    return get(handle.prepared);
}

}  // namespace

void bindPrepared(py::module_& m) {
    py::class_<PreparedHandle, std::shared_ptr<PreparedHandle>>(
        m, "PreparedScene",
        "A scene made ready for frames (flattened once; what techniques derive from it built on first use). "
        "Shared: a FrameHistory keeps it alive, and Frames do not need it. Its camera and lights may change "
        "between frames; a change waits for the frames rendering.")
        .def(py::init(&prepare), py::arg("scene"), "prepare(scene): checks its camera and lights (ValueError) and prepares a copy.")
        .def_property_readonly(
            "scene", [](PreparedHandle& h) { return read(h, [](const PreparedScene& p) { return p.scene(); }); },
            "a copy of its Scene, with the current camera and lights")
        .def_property(
            "camera", [](PreparedHandle& h) { return read(h, [](const PreparedScene& p) { return p.scene().camera; }); },
            [](PreparedHandle& h, const Camera& camera) { change(h, [&](PreparedScene& p) { p.setCamera(camera); }); },
            "its Camera (a value, checked where it was made); assign one to move it: "
            "prepared.camera = prepared.camera.replace(width=64)")
        .def_property(
            "lights", [](PreparedHandle& h) { return read(h, [](const PreparedScene& p) { return p.scene().lights; }); },
            [](PreparedHandle& h, std::vector<Light> lights) {
                requireValid(lights);
                change(h, [&](PreparedScene& p) { p.setLights(std::move(lights)); });
            },
            "its Lights (values), a list; assign a list to change them (their number too, at most 16)")
        .def(
            "set_instance_transforms",
            [](PreparedHandle& h, const py::dict& transforms) {
                const std::vector<InstancePlacement> placements =
                    placementsOf(read(h, [](const PreparedScene& p) { return instanceNames(p.scene()); }), transforms);
                size_t moved = 0;
                change(h, [&](PreparedScene& p) { moved = p.setInstanceTransforms(placements); });
                return moved;
            },
            py::arg("transforms"),
            "Moves instances between frames, as a fly-through does: {instance (index or name): 4 x 4 "
            "world-from-object matrix}. The world is placed again in place, and what techniques derived from "
            "the geometry is built again. ValueError, changing nothing, for an unknown instance, one given twice, "
            "a matrix that is not affine or a vertex outside the world's limits. Returns how many moved.")
        .def_property_readonly(
            "geometry_version", [](PreparedHandle& h) { return read(h, [](const PreparedScene& p) { return p.geometryVersion(); }); },
            "how many times its instances have moved");
    m.def("prepare", &prepare, py::arg("scene"),
          "A PreparedScene of a copy of the scene: checks its camera and lights by the scene format's rules "
          "(ValueError), then flattens it with the GIL released.");
}

}  // namespace shadowlab::python
