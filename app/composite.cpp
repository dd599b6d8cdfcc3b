#include "app/composite.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numeric>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "app/common/staged_outputs.h"
#include "app/composite_plan.h"
#include "app/plots/line_plot.h"
#include "differential/builtin_cases.h"
#include "differential/composite.h"
#include "differential/compositing_inputs.h"
#include "differential/differential_reference.h"
#include "differential/intensity_error.h"
#include "differential/scene/compositing_file.h"
#include "raster/thread_count.h"
#include "scenes/scene_file.h"
#include "scenes/write_file.h"
#include "shading/image_io.h"
#include "shading/luminance.h"

namespace shadowlab {
namespace {

CompositingScene compositingCase(const CompositeArgs& a) {
    if (a.scene.ends_with(".json")) return readCompositingInputs(loadCompositingFile(a.scene));
    const std::vector<std::string>& names = builtinCompositingCaseNames();
    if (std::ranges::find(names, a.scene) == names.end()) {
        std::string known;
        for (const std::string& name : names) known += name + ", ";
        throw std::invalid_argument("composite: unknown case '" + a.scene + "' (" + known + "or a .json file)");
    }
    const BuiltinCompositingCase c = builtinCompositingCase(a.scene, a.width, a.height, builtinDataDir());
    if (!c.note.empty()) std::printf("%s\n", c.note.c_str());
    return c.scene;
}

// What a PNG shows: the camera's 8-bit response to radiance (the LDR path's images are
// already intensities).
std::vector<uint8_t> responsePng(const DifferentialModel& m, const std::vector<glm::vec3>& image, bool intensities) {
    std::vector<uint8_t> rgb;
    rgb.reserve(image.size() * 3);
    for (const glm::vec3& c : image) {
        const glm::dvec3 v = intensities ? glm::dvec3(c) : glm::round(m.response(glm::dvec3(c)));
        for (int k = 0; k < 3; ++k) rgb.push_back(uint8_t(std::clamp(v[k], 0.0, 255.0)));
    }
    return rgb;
}

void writeImage(const std::filesystem::path& dir, const std::string& name, const DifferentialModel& m,
                const std::vector<glm::vec3>& image, bool intensities) {
    if (!intensities) {
        ImageChannels exr;
        exr.width = m.camera.width, exr.height = m.camera.height;
        setRadiance(exr, image);
        writeExr(dir / (name + ".exr"), exr);
    }
    writePng(dir / (name + ".png"), m.camera.width, m.camera.height, responsePng(m, image, intensities));
}

// The photograph, darkened, with a buffer's pixels painted over it in a colour whose
// strength grows with the value (0 leaves the pixel as it is).
void writeOverlay(const std::filesystem::path& path, const DifferentialModel& m, const std::vector<uint8_t>& values,
                  int fullScale, const glm::vec3& colour) {
    std::vector<uint8_t> rgb = responsePng(m, m.background, false);
    for (size_t k = 0; k < values.size(); ++k) {
        const float t = std::min(1.0f, float(values[k]) / float(fullScale));
        for (int c = 0; c < 3; ++c) {
            const float base = 0.5f * float(rgb[3 * k + c]);
            rgb[3 * k + c] = uint8_t(values[k] ? base + t * (255.0f * colour[c] - base) : base);
        }
    }
    writePng(path, m.camera.width, m.camera.height, rgb);
}

// RMS and largest difference of the luminance over every pixel, and the RMS over the
// object's pixels and over the rest (the shadows) apart.
struct Difference {
    double rms = 0.0, max = 0.0, rmsObject = 0.0, rmsReceivers = 0.0;
};
Difference difference(const std::vector<glm::vec3>& reference, const std::vector<glm::vec3>& image,
                      const std::vector<uint8_t>& objectPixels) {
    Difference d;
    size_t objectCount = 0;
    for (size_t k = 0; k < reference.size(); ++k) {
        const double e = double(luminance(reference[k])) - double(luminance(image[k]));
        d.rms += e * e, d.max = std::max(d.max, std::abs(e));
        (objectPixels[k] ? d.rmsObject : d.rmsReceivers) += e * e;
        objectCount += objectPixels[k];
    }
    const size_t others = reference.size() - objectCount;
    d.rms = std::sqrt(d.rms / double(reference.size()));
    d.rmsObject = objectCount ? std::sqrt(d.rmsObject / double(objectCount)) : 0.0;
    d.rmsReceivers = others ? std::sqrt(d.rmsReceivers / double(others)) : 0.0;
    return d;
}

// |reference - test| of the luminance, white at `fullScale`.
void writeErrorMap(const std::filesystem::path& path, const DifferentialModel& m,
                   const std::vector<glm::vec3>& reference, const std::vector<glm::vec3>& test, double fullScale) {
    std::vector<uint8_t> rgb;
    for (size_t k = 0; k < reference.size(); ++k) {
        const double e = (double(luminance(reference[k])) - double(luminance(test[k]))) / fullScale;
        // Red where the composite is too dark, blue where too bright.
        const uint8_t v = uint8_t(std::clamp(std::abs(e), 0.0, 1.0) * 255.0);
        rgb.insert(rgb.end(), {e > 0 ? v : uint8_t(0), uint8_t(0), e < 0 ? v : uint8_t(0)});
    }
    writePng(path, m.camera.width, m.camera.height, rgb);
}

nlohmann::ordered_json statsJson(const std::vector<TechniqueStat>& stats) {
    nlohmann::ordered_json json;
    for (const TechniqueStat& s : stats) json[s.name] = s.value;
    return json;
}

// "f<frame>-n<passes>", n "all" for 0 (built by appends: GCC 12 warns wrongly of an
// overlapping copy in a chain of string +).
std::string frameName(int frame, int passes) {
    std::string name = "f";
    name += std::to_string(frame);
    name += "-n";
    name += passes > 0 ? std::to_string(passes) : "all";
    return name;
}

double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// The darkest a shadow makes a pixel off the object: the largest share of its light taken
// (of its intensity, on the 8-bit path).
double deepestShadow(const std::vector<glm::vec3>& photograph, const std::vector<glm::vec3>& image,
                     const std::vector<uint8_t>& object) {
    double deepest = 0.0;
    for (size_t k = 0; k < image.size(); ++k) {
        const double b = luminance(photograph[k]);
        if (!object[k] && b > 0.0) deepest = std::max(deepest, 1.0 - double(luminance(image[k])) / b);
    }
    return deepest;
}

std::string passesLabel(int n) { return n > 0 ? "n = " + std::to_string(n) : std::string("n = all"); }

// Figure 3: the 8-bit path's RMS error against the share of sources occluded, for the
// paper's even split and two uneven ones.
void writeIntensityError(const std::filesystem::path& dir, const DifferentialModel& m) {
    LinePlot plot{"8-bit path: error of the two-set estimate (Gibson et al. 2003, Figure 3)",
                  "sources occluded, % of the source set", "RMS error, 8-bit levels", {}};
    std::string csv = "first_set_percent,occluded,occluded_percent,rms_levels,largest_levels\n";
    const double sources = double(m.transfers.sources.size());
    for (const double share : {0.5, 0.25, 0.1}) {
        PlotSeries series{"sets " + std::to_string(int(100 * share)) + "/" + std::to_string(int(100 - 100 * share)),
                          {}, {}, {}};
        for (const IntensityErrorPoint& p : intensityTransferError(m.transfers, m.response, share, 20)) {
            const double percent = 100.0 * p.occluded / sources;
            series.x.push_back(percent), series.y.push_back(p.rmsLevels);
            csv += std::to_string(int(100 * share)) + "," + std::to_string(p.occluded) + "," + std::to_string(percent) +
                   "," + std::to_string(p.rmsLevels) + "," + std::to_string(p.largestLevels) + "\n";
        }
        plot.series.push_back(std::move(series));
    }
    writeTextFile(dir / "ldr-error.csv", csv);
    writeTextFile(dir / "ldr-error.svg", formatLinePlotSvg(plot));
}

// The frame, and the median wall time of `runs` of it after the warm-up.
CompositeFrame timedFrame(const DifferentialModel& m, const PreparedObject& object,
                          std::span<const glm::mat4> placement, const CompositeSettings& settings,
                          const CompositeArgs& a, double& medianMs) {
    for (int w = 0; w < a.warmupRuns; ++w) compositeFrame(m, object, placement, settings);
    std::vector<double> times;
    CompositeFrame frame;
    for (int r = 0; r < std::max(1, a.runs); ++r) {
        const auto start = std::chrono::steady_clock::now();
        frame = compositeFrame(m, object, placement, settings);
        times.push_back(millisecondsSince(start));
    }
    std::sort(times.begin(), times.end());
    medianMs = times[times.size() / 2];
    return frame;
}

// The frames asked for, each checked against the path.
std::vector<int> chosenFrames(const CompositeArgs& a, const CompositingScene& scene) {
    const int count = int(scene.objects.front().path.size());
    if (a.frames.empty()) {
        std::vector<int> every(count);
        std::iota(every.begin(), every.end(), 0);
        return every;
    }
    for (const int k : a.frames) {
        if (k < 0 || k >= count) throw std::invalid_argument("composite: no such frame in the path");
    }
    return a.frames;
}

// What every frame of a run shares, and the plots it fills.
struct Run {
    const CompositeArgs& a;
    const DifferentialModel& m;
    const PreparedObject& object;
    std::filesystem::path dir;
    LinePlot timeRms, depth;   // depth: a series per n, then the reference's
};

// The reference of a frame (and, on request, its convergence), written beside the composites.
std::vector<glm::vec3> frameReference(const Run& run, int k, std::span<const glm::mat4> placement,
                                      nlohmann::ordered_json& frameJson) {
    const CompositeArgs& a = run.a;
    const auto start = std::chrono::steady_clock::now();
    PatchSampling strata = referenceSampling();
    strata.emitterSamplesPerAxis = a.referenceStrata.at(0), strata.reflectorSamplesPerAxis = a.referenceStrata.at(1);
    const std::vector<glm::vec3> reference = differentialReference(run.m, run.object, placement, strata);
    frameJson["reference_ms"] = millisecondsSince(start);
    if (a.referenceConvergence) {
        PatchSampling denser = strata;
        denser.emitterSamplesPerAxis *= 2, denser.reflectorSamplesPerAxis *= 2, denser.seed += 1;
        const std::vector<glm::vec3> dense = differentialReference(run.m, run.object, placement, denser);
        const double change = difference(reference, dense, std::vector<uint8_t>(dense.size(), 0)).rms;
        frameJson["reference_convergence_rms_radiance"] = change;
        std::printf("frame %d: the reference at twice the strata per side differs by RMS %.6f\n", k, change);
    }
    writeImage(run.dir, "reference-f" + std::to_string(k), run.m, reference, false);
    return reference;
}

// A composite's image and intermediate buffers.
void writeFrameBuffers(const Run& run, const std::string& name, const CompositeFrame& frame,
                       std::span<const glm::mat4> placement) {
    const DifferentialModel& m = run.m;
    const Scene& whole = run.object.levels.whole;
    writeImage(run.dir, (run.a.ldr ? "composite-ldr-" : "composite-") + name, m, frame.image, run.a.ldr);
    writeOverlay(run.dir / ("listed-" + name + ".png"), m, frame.listedReceiverPixels, 1, {0.2f, 0.6f, 1.0f});
    writeOverlay(run.dir / ("shadowing-" + name + ".png"), m, frame.shadowingClusters,
                 std::max<int>(1, int(frame.clusters.size())), {1.0f, 0.3f, 0.1f});
    writeTextFile(run.dir / ("plan-" + name + ".svg"),
                  formatPlanSvg(m, frame, instanceBounds(whole, placed(whole, placement))));
    for (size_t c = 0; c < frame.clusterMasks.size(); ++c) {
        writeOverlay(run.dir / ("mask-" + name + "-c" + std::to_string(c) + ".png"), m, frame.clusterMasks[c], 1,
                     {1.0f, 0.9f, 0.2f});
    }
}

// The JSON row of one frame at one n: time, stats, clusters, the deepest shadow.
nlohmann::ordered_json passRow(int n, double ms, const CompositeFrame& frame, double deepest) {
    nlohmann::ordered_json row = {{"passes", n}, {"median_ms", ms}, {"stats", statsJson(frame.stats)}};
    row["clusters"] = nlohmann::ordered_json::array();
    for (size_t c = 0; c < frame.clusters.size(); ++c) {
        const glm::dvec3& l = frame.lights[c];
        row["clusters"].push_back({{"sources", frame.clusters[c].patches.size()},
                                   {"transfer_radiance", frame.clusters[c].transfer},
                                   {"light", {l.x, l.y, l.z}}});
    }
    row["deepest_shadow_ratio"] = deepest;
    return row;
}

// Frame k at every n: composited, timed, scored against the reference, written; the plots
// get its points.
nlohmann::ordered_json runFrame(Run& run, int k, std::span<const glm::mat4> placement) {
    const CompositeArgs& a = run.a;
    const DifferentialModel& m = run.m;
    nlohmann::ordered_json frameJson = {{"frame", k}, {"passes", nlohmann::ordered_json::array()}};
    const std::vector<glm::vec3> reference =
        a.reference ? frameReference(run, k, placement, frameJson) : std::vector<glm::vec3>();
    PlotSeries frameSeries{"frame " + std::to_string(k), {}, {}, {}};
    std::vector<uint8_t> objectPixels;
    for (size_t i = 0; i < a.passes.size(); ++i) {
        const int n = a.passes[i];
        CompositeSettings settings;
        settings.passes = n, settings.resolution = a.resolution, settings.ldr = a.ldr, settings.keepMasks = a.masks;
        double ms = 0.0;
        const CompositeFrame frame = timedFrame(m, run.object, placement, settings, a, ms);
        const std::string name = frameName(k, n);
        writeFrameBuffers(run, name, frame, placement);
        const double deepest = deepestShadow(a.ldr ? m.photographIntensities : m.background, frame.image,
                                             frame.objectPixels);
        nlohmann::ordered_json row = passRow(n, ms, frame, deepest);
        objectPixels = frame.objectPixels;
        if (!a.ldr) run.depth.series[i].x.push_back(k), run.depth.series[i].y.push_back(deepest);
        if (a.reference && !a.ldr) {
            const Difference d = difference(reference, frame.image, frame.objectPixels);
            row["rms_radiance"] = d.rms, row["max_radiance"] = d.max;
            row["rms_object_radiance"] = d.rmsObject, row["rms_receivers_radiance"] = d.rmsReceivers;
            writeErrorMap(run.dir / ("error-" + name + ".png"), m, reference, frame.image, 0.05);
            frameSeries.x.push_back(ms), frameSeries.y.push_back(d.rms), frameSeries.labels.push_back(passesLabel(n));
            std::printf("frame %d, %s: %.2f ms, %zu clusters, RMS %.5f against the reference "
                        "(object %.5f, the rest %.5f)\n",
                        k, passesLabel(n).c_str(), ms, frame.clusters.size(), d.rms, d.rmsObject, d.rmsReceivers);
        } else {
            std::printf("frame %d, %s: %.2f ms, %zu clusters\n", k, passesLabel(n).c_str(), ms, frame.clusters.size());
        }
        frameJson["passes"].push_back(row);
    }
    if (a.reference && !objectPixels.empty()) {
        // The shadow's own size: the error, off the object, of leaving the photograph as it is.
        frameJson["rms_background_radiance"] = difference(reference, m.background, objectPixels).rmsReceivers;
        const double deepest = deepestShadow(m.background, reference, objectPixels);
        frameJson["reference_deepest_shadow_ratio"] = deepest;
        run.depth.series.back().x.push_back(k), run.depth.series.back().y.push_back(deepest);
    }
    if (!frameSeries.x.empty()) run.timeRms.series.push_back(std::move(frameSeries));
    return frameJson;
}

void run(const CompositeArgs& a) {
    const CompositingScene scene = compositingCase(a);
    const std::vector<int> frames = chosenFrames(a, scene);
    StagedOutputs outputs(a.outDir, {"composite.json"});
    const std::filesystem::path& dir = outputs.folder();
    PreprocessSettings preprocessSettings;
    preprocessSettings.sourceShare = a.sourceShare;
    preprocessSettings.significance = a.significance;
    const auto start = std::chrono::steady_clock::now();
    const DifferentialModel m = preprocess(scene, preprocessSettings);
    const PreparedObject object = prepareObject(m, scene.objects, {a.shadowTriangles, 0.15});
    const double preprocessMs = millisecondsSince(start);
    writeImage(dir, "background", m, m.background, false);
    nlohmann::ordered_json json = {{"case", scene.name}, {"width", m.camera.width}, {"height", m.camera.height},
                                   {"source_share", a.sourceShare}, {"significance", a.significance},
                                   {"reference_strata", a.referenceStrata}, {"map_texels", a.resolution},
                                   {"runs", a.runs}, {"warmup_runs", a.warmupRuns},
                                   {"threads", a.threads}, {"preprocess_ms", preprocessMs},
                                   {"preprocess", statsJson(m.stats)}, {"frames", nlohmann::ordered_json::array()}};
    std::printf("%s: preprocessed in %.0f ms (%zu sources, %zu receiver patches, %zu shaft leaves)\n",
                scene.name.c_str(), preprocessMs, m.transfers.sources.size(), m.transfers.receiverPatches.size(),
                m.shafts.leafCount());
    if (a.ldrError) writeIntensityError(dir, m);
    Run run{a, m, object, dir,
            {scene.name + ": time against RMS (labels: passes n)", "median ms per frame",
             "RMS against the reference (luminance)", {}},
            {scene.name + ": the deepest shadow along the path", "frame of the path",
             "largest share of a pixel's light taken", {}}};
    for (const int n : a.passes) run.depth.series.push_back({passesLabel(n), {}, {}, {}});
    run.depth.series.push_back({"reference", {}, {}, {}});
    for (const int k : frames) json["frames"].push_back(runFrame(run, k, placementsAt(scene.objects, size_t(k))));
    if (!run.timeRms.series.empty()) writeTextFile(dir / "time-rms.svg", formatLinePlotSvg(run.timeRms));
    std::erase_if(run.depth.series, [](const PlotSeries& series) { return series.x.empty(); });
    if (!run.depth.series.empty()) writeTextFile(dir / "shadow-depth.svg", formatLinePlotSvg(run.depth));
    writeTextFile(dir / "composite.json", json.dump(2) + "\n");
    outputs.commit();
}

}  // namespace

void runCompositeCommand(const CompositeArgs& args) {
    withThreads(args.threads, [&args] { run(args); });
}

}  // namespace shadowlab
