// How the extension's files turn Python values into the library's, and back: a position as
// a tuple of three floats, technique settings as the command's --param text, a SIMD level,
// a technique by name or object, and a scene from whatever load_scene() takes.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "raster/tile_kernels.h"
#include "scenes/scene.h"
#include "shadows/technique.h"

namespace shadowlab::python {

// A Python argument taken as it is, for the function to check and convert (with a one-line
// TypeError of its own, where pybind11's would list every overload), named in signatures and
// the API reference by Tag::name, the types it accepts.
template <class Tag>
struct Argument {
    pybind11::object object;
};
struct TechniqueTag {
    static constexpr auto name = pybind11::detail::const_name("Technique | str");
};
struct ParamsTag {
    static constexpr auto name = pybind11::detail::const_name("dict[str, str | int | float | bool] | None");
};
struct SimdTag {
    static constexpr auto name = pybind11::detail::const_name("str | None");
};
using TechniqueArgument = Argument<TechniqueTag>;   // techniqueOf()
using ParamsArgument = Argument<ParamsTag>;         // paramSettings()
using SimdArgument = Argument<SimdTag>;             // simdLevel()

}  // namespace shadowlab::python

namespace pybind11::detail {

template <class Tag>
struct type_caster<shadowlab::python::Argument<Tag>> {
    PYBIND11_TYPE_CASTER(shadowlab::python::Argument<Tag>, Tag::name);
    bool load(handle source, bool) {
        value.object = reinterpret_borrow<object>(source);
        return true;
    }
    static handle cast(const shadowlab::python::Argument<Tag>& argument, return_value_policy, handle) {
        return argument.object.inc_ref();
    }
};

// glm::vec3 as a tuple (x, y, z) of floats; any sequence of three real numbers converts to
// one (a list, a tuple, a numpy array), anything else is a TypeError.
template <>
struct type_caster<glm::vec3> {
    PYBIND11_TYPE_CASTER(glm::vec3, const_name("tuple[float, float, float]"));

    bool load(handle source, bool convert) {
        if (!isinstance<sequence>(source) || isinstance<str>(source)) return false;
        const sequence items = reinterpret_borrow<sequence>(source);
        if (items.size() != 3) return false;
        for (size_t k = 0; k < 3; ++k) {
            make_caster<float> component;
            if (!component.load(items[k], convert)) return false;
            value[int(k)] = cast_op<float>(component);
        }
        return true;
    }

    static handle cast(const glm::vec3& v, return_value_policy, handle) {
        return make_tuple(v.x, v.y, v.z).release();
    }
};

}  // namespace pybind11::detail

namespace shadowlab::python {

// A 4 x 4 matrix as numpy writes it, row by row (A[r][c], acting on column vectors: A @ p),
// from any nested sequence or array of 4 x 4 real numbers; TypeError for another shape.
glm::mat4 matrixOf(const pybind11::handle& matrix);
// The other way: a (4, 4) float32 array, a copy.
pybind11::object matrixArray(const glm::mat4& matrix);

// A technique's settings as the command's --param NAME=VALUE texts: a dict (or None: none)
// from names to str (as given), bool ("on"/"off"), int or float (settingText(), the shortest
// text that reads back as the same double). Throws TypeError for another key or value type.
std::map<std::string, std::string> paramSettings(const pybind11::handle& params);

// None: the best level of this CPU; a str: "scalar", "avx2", "avx512" or "auto"
// (raster::parseSimdLevel, which throws std::invalid_argument for another).
raster::SimdLevel simdLevel(const pybind11::handle& simd);

// A Technique object, or a technique's name (findTechnique, std::invalid_argument naming the
// known ones for another); the registry's own, which lives as long as the program.
const Technique& techniqueOf(const pybind11::handle& technique);

// A file path from Python (str or os.PathLike) as the library takes it: TypeError for bytes,
// ValueError for a NUL character, at which the C library would cut the path and open another
// file (open() refuses it so too).
std::string filePath(const pybind11::handle& path);

// What load_scene() takes: a Scene (copied), a built-in name or a path (str or os.PathLike;
// loadScene() against sceneDir), or a dict in the scene format's shape whose mesh paths are
// relative to baseDir (None: the working directory). Throws TypeError for anything else, and
// the loader's SceneError (MissingFileError for a file that does not exist).
Scene sceneFromSource(const pybind11::handle& source, const pybind11::handle& baseDir, const std::string& sceneDir);

// The names of a scene's instances, in order.
std::vector<std::string> instanceNames(const Scene& scene);

// A technique's stats (or a frame's preparation) as {name: value}, in their order.
pybind11::dict statsDict(const std::vector<TechniqueStat>& stats);

}  // namespace shadowlab::python
