// render() and reference(): a frame of a prepared scene on the library's threads with the GIL
// released, and FrameHistory, what a sequence of frames keeps from one to the next.
#include <filesystem>
#include <memory>
#include <mutex>
#include <shared_mutex>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "frame/render.h"
#include "frame/score.h"
#include "python/bindings.h"
#include "python/conversions.h"
#include "python/debug_readback.h"
#include "python/handles.h"
#include "raster/thread_count.h"

namespace py = pybind11;

namespace shadowlab::python {
namespace {

void checkThreads(int threads) {
    if (threads < 0 || threads > kMaxThreads)
        throw std::invalid_argument("threads must be within 0..1024 (0: every core), got " + std::to_string(threads));
}

// The frame, into a temporary debug directory read back if `debug`; the caller holds no GIL.
Frame renderWithDebug(const PreparedScene& prepared, const Technique& technique, FrameSettings settings, int threads,
                      bool debug, DebugReadback& readback) {
    if (!debug) return withThreads(threads, [&] { return renderFrame(prepared, technique, settings); });
    settings.debugDir = makeTemporaryDirectory();
    Frame frame;
    try {
        frame = withThreads(threads, [&] { return renderFrame(prepared, technique, settings); });
    } catch (...) {
        std::filesystem::remove_all(settings.debugDir);
        throw;
    }
    readback = readBackDebugBuffers(settings.debugDir);
    return frame;
}

std::shared_ptr<RenderedFrame> render(const std::shared_ptr<PreparedHandle>& prepared,
                                      const TechniqueArgument& techniqueArg, const ParamsArgument& params, int threads,
                                      const SimdArgument& simd, bool debug, const std::shared_ptr<HistoryHandle>& history) {
    if (!prepared) throw py::type_error("render() needs a PreparedScene, not None");
    checkThreads(threads);
    const Technique& technique = techniqueOf(techniqueArg.object);
    FrameSettings settings;
    settings.simd = simdLevel(simd.object);
    settings.params = paramSettings(params.object);
    auto result = std::make_shared<RenderedFrame>();
    result->technique = technique.name;
    result->settings = TechniqueParams(technique.name, technique.params, settings.params).values();
    py::gil_scoped_release release;
    std::unique_lock<std::mutex> sequence;
    if (history) {
        sequence = std::unique_lock(history->mutex);
        settings.history = &history->history;
    }
    const std::shared_lock lock(prepared->mutex);
    result->frame = renderWithDebug(prepared->prepared, technique, settings, threads, debug, result->debug);
    // Only once a frame is in the history: a first frame that failed leaves it to the next
    // frame's scene, which it must then keep alive, not the failed one's.
    if (history && !history->prepared) history->prepared = prepared;
    return result;
}

std::shared_ptr<RenderedFrame> reference(const std::shared_ptr<PreparedHandle>& prepared, const std::string& name,
                                         int threads, const SimdArgument& simd) {
    if (!prepared) throw py::type_error("reference() needs a PreparedScene, not None");
    checkThreads(threads);
    const Technique& technique = techniqueOf(py::str(name));
    const raster::SimdLevel level = simdLevel(simd.object);
    auto result = std::make_shared<RenderedFrame>();
    result->technique = technique.name;
    result->settings = TechniqueParams(technique.name, technique.params, {}).values();
    py::gil_scoped_release release;
    const std::shared_lock lock(prepared->mutex);
    result->frame = withThreads(threads, [&] { return renderReferenceFrame(prepared->prepared, level, name); });
    return result;
}

}  // namespace

void bindRender(py::module_& m) {
    py::class_<HistoryHandle, std::shared_ptr<HistoryHandle>>(
        m, "FrameHistory",
        "What a sequence of frames of one technique keeps from frame to frame (temporal techniques: "
        "docs/temporal.md). Pass the same one as render(history=...) to every frame of the sequence; it belongs "
        "to its first frame's prepared scene, technique and settings (another is a RuntimeError) and keeps that "
        "PreparedScene alive. Its frames render one at a time.")
        .def(py::init([] { return std::make_shared<HistoryHandle>(); }), "An empty history: the next frame is a sequence's first.")
        .def_property_readonly(
            "frames",
            [](HistoryHandle& h) {
                const py::gil_scoped_release release;   // a frame of the sequence may hold the lock
                const std::lock_guard lock(h.mutex);
                return h.history.frames();
            },
            "frames rendered with it so far: the next frame's index")
        .def_property_readonly(
            "prepared",
            [](HistoryHandle& h) {
                const py::gil_scoped_release release;
                const std::lock_guard lock(h.mutex);
                return h.prepared;
            },
            "the PreparedScene its frames are of, which it keeps alive; None before its first frame");
    m.def("render", &render, py::arg("prepared"), py::arg("technique"), py::arg("params") = py::none(), py::kw_only(),
          py::arg("threads") = 0, py::arg("simd") = py::none(), py::arg("debug") = false,
          py::arg("history") = py::none(),
          "A Frame of the prepared scene with the technique (a Technique or its name) and params (a dict: str, "
          "int, float or bool values, as --param NAME=VALUE gives them), on `threads` of the library's worker "
          "threads (0: every core; raster/thread_count.h's withThreads, as a sweep's), with the GIL released. simd: None "
          "(the best), \"scalar\", \"avx2\" or \"avx512\". debug: also keep the technique's intermediate buffers "
          "(Frame.debug). history: a FrameHistory this frame continues. ValueError for a bad setting.");
    m.def("reference", &reference, py::arg("prepared"), py::arg("name") = "reference", py::kw_only(),
          py::arg("threads") = 0, py::arg("simd") = py::none(),
          "The exact reference's Frame (name: \"reference\", the hard shadow of each light's centre, or "
          "\"reference-soft\"; a Technique's .reference names its own), as score() takes it.");
}

}  // namespace shadowlab::python
