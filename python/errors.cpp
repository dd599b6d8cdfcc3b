// The library's exceptions as Python's, their one-line messages kept: a bad argument or
// setting (std::invalid_argument) is a ValueError, a scene or mesh file's problem
// (SceneError) a ValueError too, a file that does not exist (MissingFileError) a
// FileNotFoundError, std::out_of_range an IndexError, a misuse of an object's
// order (std::logic_error) a RuntimeError; pybind11 maps the rest (std::runtime_error:
// RuntimeError, std::bad_alloc: MemoryError).
#include <stdexcept>

#include "python/bindings.h"
#include "scenes/scene_error.h"

namespace shadowlab::python {

void bindErrors(pybind11::module_& m) {
    // The most derived first: a SceneError is a std::runtime_error.
    pybind11::register_exception_translator([](std::exception_ptr error) {
        try {
            if (error) std::rethrow_exception(error);
        } catch (const MissingFileError& e) {
            PyErr_SetString(PyExc_FileNotFoundError, e.what());
        } catch (const SceneError& e) {
            PyErr_SetString(PyExc_ValueError, e.what());
        } catch (const std::invalid_argument& e) {
            PyErr_SetString(PyExc_ValueError, e.what());
        }
    });
    (void)m;
}

}  // namespace shadowlab::python
