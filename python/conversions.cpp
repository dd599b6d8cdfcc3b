#include "python/conversions.h"

#include <filesystem>

#include <pybind11/numpy.h>

#include "frame/registry.h"
#include "scenes/scene_file.h"
#include "shadows/technique_params.h"

namespace py = pybind11;

namespace shadowlab::python {
namespace {

// One setting's value as --param would give it; bool before int, since a bool is an int.
std::string settingOf(const std::string& name, const py::handle& value) {
    if (py::isinstance<py::str>(value)) return value.cast<std::string>();
    if (py::isinstance<py::bool_>(value)) return value.cast<bool>() ? "on" : "off";
    if (py::isinstance<py::int_>(value)) return py::str(value).cast<std::string>();
    if (py::isinstance<py::float_>(value)) return settingText(value.cast<double>());
    throw py::type_error("params: " + name + " must be a str, int, float or bool, not " +
                         std::string(py::str(value.get_type().attr("__name__"))));
}

}  // namespace

glm::mat4 matrixOf(const py::handle& matrix) {
    const py::array_t<float, py::array::c_style | py::array::forcecast> rows =
        py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(matrix);
    if (!rows || rows.ndim() != 2 || rows.shape(0) != 4 || rows.shape(1) != 4)
        throw py::type_error("a transform must be a 4 x 4 matrix of numbers (row by row, as numpy writes it)");
    glm::mat4 m;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) m[c][r] = rows.at(r, c);   // glm: m[column][row]
    return m;
}

py::object matrixArray(const glm::mat4& m) {
    py::array_t<float> rows({4, 4});
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) rows.mutable_at(r, c) = m[c][r];
    return rows;
}

std::map<std::string, std::string> paramSettings(const py::handle& params) {
    std::map<std::string, std::string> settings;
    if (params.is_none()) return settings;
    if (!py::isinstance<py::dict>(params)) throw py::type_error("params must be a dict of names to values");
    for (const auto& [key, value] : py::reinterpret_borrow<py::dict>(params)) {
        if (!py::isinstance<py::str>(key)) throw py::type_error("params: every name must be a str");
        const std::string name = key.cast<std::string>();
        settings[name] = settingOf(name, value);
    }
    return settings;
}

raster::SimdLevel simdLevel(const py::handle& simd) {
    if (simd.is_none()) return raster::bestSimdLevel();
    if (!py::isinstance<py::str>(simd)) throw py::type_error("simd must be a str (scalar, avx2, avx512, auto) or None");
    return raster::parseSimdLevel(simd.cast<std::string>());
}

const Technique& techniqueOf(const py::handle& technique) {
    if (py::isinstance<py::str>(technique)) return findTechnique(technique.cast<std::string>());
    if (py::isinstance<Technique>(technique)) return findTechnique(technique.cast<const Technique&>().name);
    throw py::type_error("technique must be a Technique or a technique's name");
}

std::string filePath(const py::handle& path) {
    const py::object text = py::module_::import("os").attr("fspath")(path);
    if (!py::isinstance<py::str>(text)) throw py::type_error("a path must be a str or os.PathLike of str, not bytes");
    std::string name = text.cast<std::string>();
    if (name.find('\0') != std::string::npos) throw py::value_error("a path must not contain a NUL character");
    return name;
}

Scene sceneFromSource(const py::handle& source, const py::handle& baseDir, const std::string& sceneDir) {
    if (py::isinstance<Scene>(source)) return source.cast<Scene>();
    if (py::isinstance<py::dict>(source)) {
        // The dict as the JSON text of a scene file in baseDir, named "<dict>" in errors.
        const std::string text = py::module_::import("json").attr("dumps")(source).cast<std::string>();
        const std::string base = baseDir.is_none() ? std::string() : filePath(baseDir);
        return parseScene(text, (std::filesystem::path(base) / "<dict>").string());
    }
    if (py::isinstance<py::str>(source) || py::hasattr(source, "__fspath__")) return loadScene(filePath(source), sceneDir);
    throw py::type_error("a scene is a Scene, a built-in scene's name, a path (str or os.PathLike) or a dict, not " +
                         std::string(py::str(source.get_type().attr("__name__"))));
}

py::dict statsDict(const std::vector<TechniqueStat>& stats) {
    py::dict d;
    for (const TechniqueStat& s : stats) d[py::str(s.name)] = s.value;
    return d;
}

std::vector<std::string> instanceNames(const Scene& scene) {
    std::vector<std::string> names;
    for (const MeshInstance& instance : scene.instances) names.push_back(instance.name);
    return names;
}

}  // namespace shadowlab::python
