// The extension module _shadowlab, which the package shadowlab (python/shadowlab/) wraps:
// the library's scenes, techniques, frames, scores and measurements, for Python
// (docs/python.md). Each part of the library is bound in a file of its own; this is their table.
#include <pybind11/pybind11.h>

#include "python/bindings.h"

PYBIND11_MODULE(_shadowlab, m) {
    m.doc() = "shadowlab's library: scenes, shadow techniques, frames and their scores, sweeps and fly-throughs";
    m.attr("__version__") = SHADOWLAB_VERSION;
    using namespace shadowlab::python;
    bindErrors(m);
    bindView(m);
    bindScene(m);
    bindPrepared(m);
    bindTechniques(m);
    bindFrame(m);
    bindRender(m);
    bindScore(m);
    bindMeasure(m);
}
