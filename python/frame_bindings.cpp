// Frame and LightPass: a rendered frame's buffers as numpy views (array_views.h) that keep the
// frame alive, its figures as Python values, and the image and EXR the command writes of it.
#include <map>
#include <string>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "frame/aov_image.h"
#include "python/array_views.h"
#include "python/bindings.h"
#include "python/conversions.h"
#include "python/handles.h"
#include "shading/tonemap.h"

namespace py = pybind11;

namespace shadowlab::python {
namespace {

// Copies (the buffers' files are gone): floats (H, W) for a buffer of one channel, (H, W, 3)
// for R G B; uint8 (H, W, 3) for a picture.
py::dict debugDict(const DebugReadback& debug) {
    py::dict d;
    for (const auto& [name, image] : debug.buffers) {
        const py::ssize_t h = image.height, w = image.width, n = py::ssize_t(image.names.size());
        py::array_t<float> a(n == 1 ? std::vector<py::ssize_t>{h, w} : std::vector<py::ssize_t>{h, w, n});
        float* out = a.mutable_data();
        for (py::ssize_t p = 0; p < h * w; ++p)
            for (py::ssize_t c = 0; c < n; ++c) out[p * n + c] = image.data[size_t(c)][size_t(p)];
        d[py::str(name)] = a;
    }
    for (const auto& [name, picture] : debug.pictures) {
        py::array_t<uint8_t> a({picture.height, picture.width, 3});
        std::copy(picture.rgb.begin(), picture.rgb.end(), a.mutable_data());
        d[py::str(name)] = a;
    }
    return d;
}

py::array_t<uint8_t> srgb(const RenderedFrame& f, float exposure) {
    const std::vector<uint8_t> rgb = toSrgb8Image(f.frame.radiance, {exposure, ToneOperator::Reinhard});
    py::array_t<uint8_t> a({f.frame.gbuffer.height, f.frame.gbuffer.width, 3});
    std::copy(rgb.begin(), rgb.end(), a.mutable_data());
    return a;
}

// A view of the buffer `select` picks of the frame `self` (a Frame or a LightPass's frame),
// whose base is `self`.
template <class Select>
py::object frameView(const py::object& self, RenderedFrame& f, Select select) {
    return bufferView(self, select(f.frame), f.frame.gbuffer.width, f.frame.gbuffer.height);
}

template <class Select>
py::object passView(const py::object& self, Select select) {
    const PassView& v = self.cast<const PassView&>();
    return frameView(self, *v.frame, [&](Frame&) -> auto& { return select(v.pass().shadow); });
}

void bindLightPass(py::module_& m) {
    py::class_<PassView>(m, "LightPass", "One light's pass of a Frame (it keeps the Frame alive).")
        .def_property_readonly("light", [](const PassView& v) { return v.pass().light; }, "its index in the scene's lights")
        .def_property_readonly("technique_ms", [](const PassView& v) { return v.pass().techniqueMs; },
                               "the technique's wall time for this light (ms)")
        .def_property_readonly("stats", [](const PassView& v) { return statsDict(v.pass().shadow.stats); },
                               "the technique's figures for this light")
        .def_property_readonly(
            "visibility", [](py::object self) { return passView(self, [](ShadowOutputs& s) -> auto& { return s.visibility; }); },
            "V (H, W) float32, a view; None for a radiance technique")
        .def_property_readonly(
            "stencil", [](py::object self) { return passView(self, [](ShadowOutputs& s) -> auto& { return s.stencil; }); },
            "the technique's stencil (H, W) float32, a view; None if it has none")
        .def_property_readonly(
            "coloured_visibility",
            [](py::object self) { return passView(self, [](ShadowOutputs& s) -> auto& { return s.colouredVisibility; }); },
            "the light passed per channel through tinted casters (H, W, 3), a view; None where none is tinted");
}

}  // namespace

void bindFrame(py::module_& m) {
    bindLightPass(m);
    py::class_<RenderedFrame, std::shared_ptr<RenderedFrame>> frame(
        m, "Frame",
        "A rendered frame. Its buffers are numpy views without a copy (writable; each keeps the Frame alive), "
        "row 0 at the top; .debug and .srgb() are copies.");
    const auto view = [&](const char* name, auto select, const char* doc) {
        frame.def_property_readonly(
            name, [select](py::object self) { return frameView(self, self.cast<RenderedFrame&>(), select); }, doc);
    };
    // The first pass's V, not Frame::shadow's copy of it: score() and write_exr() read the
    // passes, so a write through this view must land there.
    view("visibility", [](Frame& f) -> auto& { return f.passes.empty() ? f.shadow.visibility : f.passes[0].shadow.visibility; },
         "V (H, W) float32 of the first light (passes: every light's); None for a radiance technique");
    view("radiance", [](Frame& f) -> auto& { return f.radiance; }, "the shaded image, linear (H, W, 3) float32");
    view("position", [](Frame& f) -> auto& { return f.gbuffer.position; }, "P, world space (H, W, 3); 0 where hit = 0");
    view("normal", [](Frame& f) -> auto& { return f.gbuffer.normal; }, "N, the geometric normal facing the camera (H, W, 3)");
    view("shading_normal", [](Frame& f) -> auto& { return f.gbuffer.shadingNormal; },
         "Ns, the smooth shading normal (H, W, 3)");
    view("depth", [](Frame& f) -> auto& { return f.gbuffer.depth; }, "window depth (H, W) float32; 1 is the background");
    view("hit", [](Frame& f) -> auto& { return f.gbuffer.hit; }, "1 where a surface covers the pixel centre (H, W) uint8");
    view("material", [](Frame& f) -> auto& { return f.gbuffer.material; }, "the scene's material index (H, W) uint32");
    view("triangle", [](Frame& f) -> auto& { return f.gbuffer.triangle; },
         "the world triangle index (H, W) uint32; 0xffffffff for none");
    view("stencil", [](Frame& f) -> auto& { return f.shadow.stencil; },
         "the first light's stencil (H, W); None if the technique has none");
    view("coloured_visibility", [](Frame& f) -> auto& { return f.shadow.colouredVisibility; },
         "the first light's light passed per channel (H, W, 3); None where no caster is tinted");
    view("motion", [](Frame& f) -> auto& { return f.gbuffer.motion.pixelOffset; },
         "motion vectors (H, W, 2) in pixels, x right and y down; None without a frame before (a FrameHistory's first)");
    frame
        .def_property_readonly("width", [](const RenderedFrame& f) { return f.frame.gbuffer.width; }, "W, pixels")
        .def_property_readonly("height", [](const RenderedFrame& f) { return f.frame.gbuffer.height; }, "H, pixels")
        .def_readonly("technique", &RenderedFrame::technique, "the technique's name")
        .def_readonly("settings", &RenderedFrame::settings, "every setting of the technique as text, defaults included")
        .def_property_readonly(
            "output", [](const RenderedFrame& f) { return f.frame.output == TechniqueOutput::Visibility ? "visibility" : "radiance"; },
            "the technique's output: \"visibility\" or \"radiance\"")
        .def_property_readonly("technique_ms", [](const RenderedFrame& f) { return f.frame.techniqueMs; },
                               "the technique's wall time, the sum over the lights (ms)")
        .def_property_readonly("stats", [](const RenderedFrame& f) { return statsDict(f.frame.shadow.stats); },
                               "the technique's figures (several lights: lightK_NAME), as the command prints them")
        .def_property_readonly("preparation", [](const RenderedFrame& f) { return statsDict(f.frame.preparation); },
                               "scene preparation this frame did, outside technique_ms (ms)")
        .def_property_readonly(
            "passes", [](const std::shared_ptr<RenderedFrame>& f) {
                std::vector<PassView> passes;
                for (size_t k = 0; k < f->frame.passes.size(); ++k) passes.push_back({f, k});
                return passes;
            }, "every light's LightPass, in the order of the scene's lights")
        .def_property_readonly("debug", [](const RenderedFrame& f) { return debugDict(f.debug); },
                               "the technique's intermediate buffers (render(debug=True)) by name: copies")
        .def("srgb", &srgb, py::arg("exposure") = 0.0f,
             "The image as the command's PNG has it: (H, W, 3) uint8 sRGB, tone mapped (Reinhard, exposure in "
             "stops); a copy.")
        .def("write_exr", [](const RenderedFrame& f, const py::object& path) { writeExr(filePath(path), aovImage(f.frame)); },
             py::arg("path"), "Writes (path: str or os.PathLike) the EXR `shadowlab render --aov` writes of this frame (the same bytes).")
        .def("__repr__", [](const RenderedFrame& f) {
            return "<Frame " + f.technique + " " + std::to_string(f.frame.gbuffer.width) + " x " +
                   std::to_string(f.frame.gbuffer.height) + ">";
        });
}

}  // namespace shadowlab::python
