// The library's exceptions as Python's, their one-line messages kept: a bad argument or
// setting (std::invalid_argument) is a ValueError, a scene or mesh file's problem
// (SceneError) a ValueError too, a file that does not exist (MissingFileError) a
// FileNotFoundError, std::out_of_range an IndexError, a misuse of an object's
// order (std::logic_error) a RuntimeError; pybind11 maps the rest (std::runtime_error:
// RuntimeError, std::bad_alloc: MemoryError). The messages quote what the caller gave (a
// value, a path), so control characters are escaped as the command's printer escapes them
// (scenes/error_text.h): a newline in a value would split the message (a NUL still ends
// it: what() is a C string).
#include <stdexcept>

#include "python/bindings.h"
#include "scenes/error_text.h"
#include "scenes/scene_error.h"

namespace shadowlab::python {

void bindErrors(pybind11::module_& m) {
    // The most derived first: a SceneError is a std::runtime_error.
    pybind11::register_exception_translator([](std::exception_ptr error) {
        try {
            if (error) std::rethrow_exception(error);
        } catch (const MissingFileError& e) {
            PyErr_SetString(PyExc_FileNotFoundError, oneLine(e.what()).c_str());
        } catch (const SceneError& e) {
            PyErr_SetString(PyExc_ValueError, oneLine(e.what()).c_str());
        } catch (const std::invalid_argument& e) {
            PyErr_SetString(PyExc_ValueError, oneLine(e.what()).c_str());
        }
    });
    (void)m;
}

}  // namespace shadowlab::python
