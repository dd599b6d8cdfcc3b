// ErrorFigures and score(): a frame against its reference with the figures and names of
// `shadowlab render --error-map --json` (shading/compare.h, formatJson), FLIP included.
#include <memory>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "frame/score.h"
#include "python/bindings.h"
#include "python/handles.h"
#include "shading/compare.h"

namespace py = pybind11;

namespace shadowlab::python {
namespace {

py::object asDict(const ErrorFigures& figures) {
    return py::module_::import("json").attr("loads")(formatJson(figures));
}

std::shared_ptr<RenderedFrame> required(const std::shared_ptr<RenderedFrame>& frame, const char* what) {
    if (!frame) throw py::type_error(std::string("score(): the ") + what + " must be a Frame, not None");
    return frame;
}

// Two frames of one view: a reference of another size is a wrong argument (ValueError), not
// the data error of two image files that differ (compareImages' runtime_error).
void requireOneSize(const RenderedFrame& reference, const RenderedFrame& frame) {
    const GBuffer &r = reference.frame.gbuffer, &f = frame.frame.gbuffer;
    if (r.width != f.width || r.height != f.height)
        throw std::invalid_argument("score(): the reference is " + std::to_string(r.width) + " x " +
                                    std::to_string(r.height) + " and the frame " + std::to_string(f.width) + " x " +
                                    std::to_string(f.height) + ": render both of the same view");
}

ErrorFigures score(const std::shared_ptr<RenderedFrame>& referenceArg, const std::shared_ptr<RenderedFrame>& frameArg) {
    const std::shared_ptr<RenderedFrame> reference = required(referenceArg, "reference"), frame = required(frameArg, "frame");
    requireOneSize(*reference, *frame);
    py::gil_scoped_release release;
    const ScoredReference scored = scoredReference(reference->frame);
    return scoreFrame(scored, scoredImage(frame->frame), frame->frame);
}

std::vector<ErrorFigures> scoreEachLight(const std::shared_ptr<RenderedFrame>& reference,
                                         const std::shared_ptr<RenderedFrame>& frame) {
    requireOneSize(*required(reference, "reference"), *required(frame, "frame"));
    const ImageChannels test = scoredImage(frame->frame);
    py::gil_scoped_release release;
    return scoreLights(scoredImage(reference->frame), test);
}

}  // namespace

void bindScore(py::module_& m) {
    py::class_<ErrorFigures> figures(
        m, "ErrorFigures",
        "A frame's figures against its reference, named as the JSON of `shadowlab render --error-map --json` "
        "names them (\"errors\"): each is a property, and as_dict() gives them all.");
    // One property per figure the JSON has: its names are the figures' (rms_display and
    // flip_mean where they are set, None otherwise).
    ErrorFigures every;
    every.rmsDisplay = every.flipMean = 0.0;
    for (const auto& [key, value] : asDict(every).cast<py::dict>()) {
        const std::string name = key.cast<std::string>();
        figures.def_property_readonly(
            name.c_str(), [name](const ErrorFigures& f) { return asDict(f).attr("get")(name); },
            ("the JSON's \"" + name + "\"").c_str());
    }
    figures.def("as_dict", &asDict, "Every figure by name, as the command's JSON has them.")
        .def("to_json", &formatJson, "The JSON text the command writes for these figures.")
        .def("__repr__", [](const ErrorFigures& f) {
            return "<ErrorFigures " + f.channel + ": rms " + std::to_string(f.rms) + " over " + std::to_string(f.pixels) +
                   " pixels>";
        });
    m.def("score", &score, py::arg("reference"), py::arg("frame"),
          "The frame's ErrorFigures against the reference's Frame (reference()), over the reference's hit pixels: "
          "on V for a visibility technique, on luminance for a radiance one; with several lights, over every "
          "light (score_lights gives each its own). ValueError if the two are of different outputs or sizes.");
    m.def("score_lights", &scoreEachLight, py::arg("reference"), py::arg("frame"),
          "Each light's ErrorFigures (V against V), in the order of the lights.");
}

}  // namespace shadowlab::python
