// The parts of the extension module (python/module.cpp), one function per file that binds it.
#pragma once

#include <pybind11/pybind11.h>

namespace shadowlab::python {

// The library's exceptions as Python's (errors.cpp): std::invalid_argument as ValueError, a
// scene file that is missing as FileNotFoundError, ...
void bindErrors(pybind11::module_& m);

// Sweeps and fly-throughs, their results and a sweep's JSON (measure_bindings.cpp).
void bindMeasure(pybind11::module_& m);

}  // namespace shadowlab::python
