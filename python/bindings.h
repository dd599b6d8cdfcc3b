// The parts of the extension module (python/module.cpp), one function per file that binds it.
#pragma once

#include <pybind11/pybind11.h>

namespace shadowlab::python {

// The library's exceptions as Python's (errors.cpp): std::invalid_argument as ValueError, a
// scene file that is missing as FileNotFoundError, ...
void bindErrors(pybind11::module_& m);
// Camera and Light (view_bindings.cpp).
void bindView(pybind11::module_& m);
// Scene and its loading (scene_bindings.cpp).
void bindScene(pybind11::module_& m);
// PreparedScene and prepare() (prepared_bindings.cpp).
void bindPrepared(pybind11::module_& m);
// Technique, Param, techniques() and technique() (technique_bindings.cpp).
void bindTechniques(pybind11::module_& m);
// Frame and LightPass (frame_bindings.cpp).
void bindFrame(pybind11::module_& m);
// render(), reference() and FrameHistory (render_bindings.cpp).
void bindRender(pybind11::module_& m);
// ErrorFigures, score() and score_lights() (score_bindings.cpp).
void bindScore(pybind11::module_& m);

// Sweeps and fly-throughs, their results and a sweep's JSON (measure_bindings.cpp).
void bindMeasure(pybind11::module_& m);

}  // namespace shadowlab::python
