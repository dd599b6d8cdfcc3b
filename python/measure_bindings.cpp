// Sweeps and fly-throughs for Python (docs/python.md, "Sweeps" and "Fly-throughs"): the
// library's runSweep and runFlythrough with the GIL released, their results as objects,
// and a sweep's JSON both ways, so that shards run anywhere (the Dask path of
// shadowlab/sweeps.py) travel as the command's text and merge as merge-sweep merges them.
#include <array>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/stl.h>

#include "app/measure/flythrough.h"
#include "app/measure/flythrough_report.h"
#include "app/measure/sweep.h"
#include "app/measure/sweep_json.h"
#include "app/measure/sweep_merge.h"
#include "app/plots/sweep_plot.h"
#include "frame/overrides_json.h"
#include "frame/registry.h"
#include "python/bindings.h"
#include "python/conversions.h"

namespace py = pybind11;

namespace shadowlab::python {
namespace {

// {name: value or list of values} -> the sweep's axes, in the dict's order; each value as
// render()'s params read it (paramSettings: str as given, bool on/off, the shortest float).
std::vector<SweepAxis> axesOf(const py::handle& params) {
    std::vector<SweepAxis> axes;
    if (params.is_none()) return axes;
    if (!py::isinstance<py::dict>(params)) throw py::type_error("params must be a dict of names to a value or a list of values");
    for (const auto& [name, values] : py::reinterpret_borrow<py::dict>(params)) {
        const bool several = py::isinstance<py::list>(values) || py::isinstance<py::tuple>(values) ||
                             py::isinstance(values, py::module_::import("builtins").attr("range"));
        SweepAxis axis;
        const py::iterable each = several ? py::reinterpret_borrow<py::iterable>(values) : py::iterable(py::make_tuple(values));
        for (const py::handle value : each) {
            if (axis.values.size() == kMaxSweepSettings)   // planSweep's limit, before a huge axis fills the memory
                throw std::invalid_argument("params: " + py::str(name).cast<std::string>() + " has more than " +
                                            std::to_string(kMaxSweepSettings) + " values");
            py::dict one;
            one[name] = value;
            const std::map<std::string, std::string> setting = paramSettings(one);
            axis.name = setting.begin()->first;
            axis.values.push_back(setting.begin()->second);
        }
        if (axis.values.empty()) throw std::invalid_argument("params: " + py::str(name).cast<std::string>() + " has no values");
        axes.push_back(std::move(axis));
    }
    return axes;
}

// None: the whole sweep; "i/n" or (i, n), read and checked as --shard i/n is.
SweepShard shardOf(const py::object& shard) {
    if (shard.is_none()) return {};
    if (py::isinstance<py::str>(shard)) return parseSweepShard(shard.cast<std::string>());
    const std::pair<int, int> pair = shard.cast<std::pair<int, int>>();
    return parseSweepShard(std::to_string(pair.first) + "/" + std::to_string(pair.second));
}

std::vector<const Technique*> techniquesOf(const std::vector<std::string>& names) {
    std::vector<const Technique*> techniques;
    for (const std::string& name : names) techniques.push_back(&findTechnique(name));
    return techniques;
}

py::object jsonValue(const std::string& text) { return py::module_::import("json").attr("loads")(text); }

py::dict gridDict(const SweepGrid& g) {
    py::dict axes;
    for (const SweepAxis& axis : g.axes) axes[py::str(axis.name)] = axis.values;
    py::dict d;
    d["axes"] = axes;
    d["overrides"] = jsonValue(overridesJson(g.overrides).dump());
    d["reference"] = g.reference;
    d["reference_fingerprints"] = g.referenceFingerprints;
    d["threads"] = g.threads;
    d["warmup"] = g.warmupRuns;
    d["runs"] = g.runs;
    d["settings"] = g.settings;
    return d;
}

// The scene comes loaded (load_scene() in the package, which finds the built-in scenes where
// the package is installed); the library records the overrides in the grid, so they are
// passed on, not applied here.
SweepResults sweep(const Scene& scene, const std::vector<std::string>& techniques,
                   const py::object& params,
                   const std::vector<int>& threads, int runs, int warmup, const std::string& reference,
                   const py::object& shard, const py::object& simd, std::optional<int> light,
                   std::optional<int> width, std::optional<int> height, std::optional<glm::vec3> eye,
                   std::optional<glm::vec3> target, std::optional<float> fovyDeg,
                   std::optional<glm::vec3> lightPosition, std::optional<float> lightRadius) {
    SweepOptions options;
    options.techniques = techniquesOf(techniques);
    options.axes = axesOf(params);
    options.threads = threads;
    options.runs = runs;
    options.warmupRuns = warmup;
    options.reference = reference;
    options.shard = shardOf(shard);
    options.simd = simdLevel(simd);
    options.overrides = {light, width, height, eye, target, lightPosition, fovyDeg, lightRadius};
    py::gil_scoped_release release;
    return runSweep(scene, options);
}

FlythroughResults flythrough(const Scene& scene, const std::vector<std::string>& techniques,
                             const py::object& params,
                             const py::object& path, int frames, int threads, int runs, int warmup,
                             std::optional<float> stableTolerance, const py::object& simd,
                             std::optional<int> light, std::optional<int> width, std::optional<int> height) {
    FlythroughOptions options;
    options.techniques = techniquesOf(techniques);
    options.axes = axesOf(params);
    options.pathFile = filePath(path);
    options.frames = frames;
    options.threads = threads;
    options.runs = runs;
    options.warmupRuns = warmup;
    if (stableTolerance) options.stableTolerance = *stableTolerance;
    options.simd = simdLevel(simd);
    options.overrides.light = light;
    options.overrides.width = width;
    options.overrides.height = height;
    py::gil_scoped_release release;
    return runFlythrough(scene, options);
}

// The library reports a sweep's JSON or shards that do not fit as std::runtime_error, as a
// file's problem; here they are values the caller passed: ValueError.
template <class F>
auto asValueError(F f) {
    try {
        return f();
    } catch (const std::runtime_error& e) {
        throw py::value_error(e.what());
    }
}

SweepResults mergeSweeps(const std::vector<SweepResults>& shards) {
    std::vector<SweepShardFile> files;
    for (size_t k = 0; k < shards.size(); ++k) files.push_back({"results[" + std::to_string(k) + "]", shards[k]});
    return asValueError([&] { return mergeSweepShards(files); });
}

void bindSweep(py::module_& m) {
    py::class_<SweepRow>(m, "SweepRow", "One row of a sweep: a technique setting at one thread count, timed and scored "
                                        "(the command's CSV and JSON row).")
        .def_readonly("setting", &SweepRow::setting, "index of the setting in the sweep's fixed order (from 0)")
        .def_readonly("technique", &SweepRow::technique, "the technique's name")
        .def_readonly("reference", &SweepRow::reference, "the reference it was scored against")
        .def_readonly("settings", &SweepRow::settings, "this row's axis values as text, {name: value} (defaults left out)")
        .def_property_readonly("settings_label", &SweepRow::settingsLabel, "the settings as \"a=1 b=2\", or \"defaults\"")
        .def_readonly("threads", &SweepRow::threads, "worker threads the row was measured with")
        .def_readonly("median_ms", &SweepRow::medianMs, "median of the measured frames' technique time, ms")
        .def_readonly("min_ms", &SweepRow::minMs, "minimum of the measured frames' technique time, ms")
        .def_readonly("errors", &SweepRow::errors, "ErrorFigures over every light of the scene (the last measured frame's)")
        .def_readonly("light_errors", &SweepRow::lightErrors,
                      "each light's ErrorFigures, in the scene's order, for a scene of several lights; [] for one")
        .def_property_readonly("stats", [](const SweepRow& r) { return statsDict(r.stats); },
                               "the technique's stats of the last measured frame, {name: value} (stage times: medians)")
        .def("__repr__", [](const SweepRow& r) {
            return "<SweepRow " + r.technique + " " + r.settingsLabel() + " threads=" + std::to_string(r.threads) + ">";
        });

    py::class_<SweepResults>(m, "SweepResults",
                             "A sweep's results (shadowlab.sweep, or a sweep's JSON read back): its grid and rows, "
                             "written as the command writes them; pickled as that JSON text.")
        .def_readonly("scene", &SweepResults::scene, "the scene's name")
        .def_readonly("techniques", &SweepResults::techniques, "the techniques' names, in the order given")
        .def_property_readonly("grid", [](const SweepResults& r) { return gridDict(r.grid); },
                               "what the sweep was asked for, as the JSON's \"grid\": {axes: {name: [values]}, overrides, "
                               "reference, reference_fingerprints, threads, warmup, runs, settings} (a copy)")
        .def_property_readonly("shard", [](const SweepResults& r) { return std::pair(r.shard.index, r.shard.count); },
                               "(i, n): the part of the sweep the rows cover, (1, 1) for the whole")
        .def_readonly("rows", &SweepResults::rows,
                      "list of SweepRow: per technique, its settings in axis order (last axis fastest), then threads "
                      "(a copy)")
        .def("to_json", &formatSweepJson, "The sweep's JSON: the bytes `shadowlab sweep` writes (UTF-8), as str.")
        .def("to_csv", &formatSweepCsv, "The sweep's CSV: the bytes `shadowlab sweep` writes, as str.")
        .def("to_text", &formatSweepText, "The table `shadowlab sweep` prints.")
        .def("to_svg", [](const SweepResults& r, const std::string& plotY) {
            const PlotErrorAxis axis = parsePlotErrorAxis(plotY);
            requirePlottable(r.rows, axis);
            return formatSweepSvg(r, axis);
        }, py::arg("plot_y") = "auto",
             "The speed-against-error plot `shadowlab sweep` writes (SVG text, no plotting library): plot_y is its "
             "--plot-y, auto, misclassified, rms, umbra, rms-display or flip; ValueError for an axis a row has no "
             "figure for.")
        .def_static("from_json", [](const std::string& text) { return asValueError([&] { return parseSweepJson(text, "JSON text"); }); },
                    py::arg("text"),
                    "A sweep's JSON text (to_json(), or a file `shadowlab sweep` wrote) back into results that write "
                    "the same bytes; ValueError for text that is not a sweep's JSON.")
        .def(py::pickle([](const SweepResults& r) { return formatSweepJson(r); },
                        [](const std::string& text) {
                            return asValueError([&] { return parseSweepJson(text, "a pickled SweepResults"); });
                        }))
        .def("__repr__", [](const SweepResults& r) {
            return "<SweepResults " + r.scene + " shard " + r.shard.name() + ", " + std::to_string(r.rows.size()) +
                   " rows>";
        });

    m.def("_sweep", &sweep, py::arg("scene"), py::arg("techniques"), py::arg("params"), py::arg("threads"),
          py::arg("runs"), py::arg("warmup"), py::arg("reference"), py::arg("shard"), py::arg("simd"),
          py::arg("light"), py::arg("width"), py::arg("height"), py::arg("eye"), py::arg("target"), py::arg("fovy_deg"),
          py::arg("light_position"), py::arg("light_radius"),
          "runSweep with the GIL released; shadowlab.sweep is its front end.");
    m.def("_sweep_settings", [](const std::vector<std::string>& techniques, const py::object& params) {
        return settingCount(planSweep(techniquesOf(techniques), axesOf(params)));
    }, py::arg("techniques"), py::arg("params"), "The settings a sweep of these techniques and axes runs, all shards' (planSweep's checks).");
    m.def("_check_shard_count", &checkShardCount, py::arg("count"), py::arg("settings"),
          "ValueError unless a sweep of `settings` settings splits into `count` shards that each hold one.");
    m.def("merge_sweeps", &mergeSweeps, py::arg("shards"),
          "The SweepResults of every shard of one sweep joined into the whole sweep's, as `shadowlab merge-sweep` "
          "joins their files: ValueError unless they are parts of one sweep (same scene, techniques and grid), "
          "each shard i/n given once and none missing. Rows in the unsharded order; shard (1, 1).");
}

py::dict flickerDict(const std::optional<FlickerFigures>& f) {
    py::dict d;
    if (!f) return d;
    d["mean"] = f->mean;
    d["p99"] = f->p99;
    d["pixels"] = f->pixels;
    d["stable_pixels"] = f->stablePixels;
    return d;
}

py::dict pathFiguresDict(const FlythroughSeries& series) {
    const PathFigures p = pathFigures(series);
    py::dict d;
    d["median_ms"] = p.medianMs;
    d["mean_rms"] = p.meanRms;
    d["mean_flip"] = p.meanFlip;
    d["mean_misclassified_percent"] = p.meanMisclassifiedPercent;
    d["flicker_mean"] = p.flickerMean;
    d["flicker_p99"] = p.flickerP99;
    d["settle_frames"] = p.settleFrames;
    d["settled"] = p.settled;
    d["ghosting_rms_frames"] = p.ghosting;
    return d;
}

std::array<float, 3> xyzOf(const glm::vec3& v) { return xyz(v); }

void bindFlythrough(py::module_& m) {
    py::class_<FlythroughFrame>(m, "FlythroughFrame", "One frame of a fly-through series: where the path was, the "
                                                      "technique's time, its error and its flicker.")
        .def_readonly("frame", &FlythroughFrame::frame, "the frame's number, from 0")
        .def_readonly("time", &FlythroughFrame::time, "the path's time of the frame")
        .def_property_readonly("eye", [](const FlythroughFrame& f) { return xyzOf(f.eye); }, "the camera's eye, (x, y, z)")
        .def_property_readonly("target", [](const FlythroughFrame& f) { return xyzOf(f.target); },
                               "the camera's target, (x, y, z)")
        .def_property_readonly("light", [](const FlythroughFrame& f) {
            return f.light ? std::optional(xyzOf(*f.light)) : std::nullopt;
        }, "where the path put the first light, (x, y, z), or None if it does not move it")
        .def_readonly("moved", &FlythroughFrame::moved, "the camera, the light or an instance differs from the frame before")
        .def_readonly("median_ms", &FlythroughFrame::medianMs, "median of the measured runs' technique time, ms")
        .def_readonly("min_ms", &FlythroughFrame::minMs, "minimum of the measured runs' technique time, ms")
        .def_readonly("errors", &FlythroughFrame::errors, "ErrorFigures against the frame's exact reference")
        .def_property_readonly("flicker", [](const FlythroughFrame& f) { return flickerDict(f.flicker); },
                               "against the frame before: {mean, p99, pixels, stable_pixels}; {} for frame 0")
        .def_property_readonly("stats", [](const FlythroughFrame& f) { return statsDict(f.stats); },
                               "the technique's stats for the frame, {name: value}");

    py::class_<FlythroughSeries>(m, "FlythroughSeries", "One technique setting along the whole path.")
        .def("__repr__", [](const FlythroughSeries& s) {
            return "<FlythroughSeries " + s.label() + ", " + std::to_string(s.frames.size()) + " frames>";
        })
        .def_readonly("technique", &FlythroughSeries::technique, "the technique's name")
        .def_readonly("reference", &FlythroughSeries::reference, "the reference it was scored against")
        .def_readonly("settings", &FlythroughSeries::settings, "its axis values as text, {name: value}")
        .def_property_readonly("label", &FlythroughSeries::label, "\"csm snap=off\", or the technique alone")
        .def_readonly("frames", &FlythroughSeries::frames, "list of FlythroughFrame, in the path's order (a copy)")
        .def_property_readonly("path_figures", &pathFiguresDict,
                               "the series over the path, as the JSON's \"path_figures\": {median_ms, mean_rms, "
                               "mean_flip, mean_misclassified_percent, flicker_mean, flicker_p99, settle_frames, "
                               "settled, ghosting_rms_frames} (None where the path does not end still)");

    py::class_<FlythroughResults>(m, "FlythroughResults", "A fly-through's results (shadowlab.flythrough).")
        .def_readonly("scene", &FlythroughResults::scene, "the scene's name")
        .def_readonly("path", &FlythroughResults::path, "the keyframes' CSV file, or \"scene\" for the scene's own path")
        .def_readonly("frames", &FlythroughResults::frames, "frames sampled along the path")
        .def_readonly("threads", &FlythroughResults::threads, "worker threads, as run")
        .def_readonly("warmup", &FlythroughResults::warmupRuns, "warm-up runs per path frame")
        .def_readonly("runs", &FlythroughResults::runs, "measured runs per path frame")
        .def_readonly("stable_tolerance", &FlythroughResults::stableTolerance,
                      "the reference's V counts as unchanged if it moves by at most this")
        .def_readonly("series", &FlythroughResults::series, "list of FlythroughSeries, per technique and setting (a copy)")
        .def("to_json", &formatFlythroughJson, "The fly-through's JSON: the bytes `shadowlab flythrough` writes, as str.")
        .def("to_csv", &formatFlythroughCsv, "The fly-through's CSV: the bytes `shadowlab flythrough` writes, as str.")
        .def("to_text", &formatFlythroughText, "The summary `shadowlab flythrough` prints.")
        .def("__repr__", [](const FlythroughResults& r) {
            return "<FlythroughResults " + r.scene + ", " + std::to_string(r.series.size()) + " series of " +
                   std::to_string(r.frames) + " frames>";
        });

    m.def("_flythrough", &flythrough, py::arg("scene"), py::arg("techniques"), py::arg("params"), py::arg("path"),
          py::arg("frames"), py::arg("threads"), py::arg("runs"), py::arg("warmup"), py::arg("stable_tolerance"),
          py::arg("simd"), py::arg("light"), py::arg("width"), py::arg("height"),
          "runFlythrough with the GIL released; shadowlab.flythrough is its front end.");
}

}  // namespace

void bindMeasure(py::module_& m) {
    bindSweep(m);
    bindFlythrough(m);
}

}  // namespace shadowlab::python
