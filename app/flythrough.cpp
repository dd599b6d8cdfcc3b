#include "app/flythrough.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <stdexcept>

#include <tbb/info.h>

#include "app/sweep.h"
#include "frame/score.h"
#include "raster/thread_count.h"
#include "scenes/camera_path.h"
#include "scenes/read_file.h"
#include "scenes/scene_file.h"
#include "scenes/scene_limits.h"
#include "shading/tonemap.h"

namespace shadowlab {
namespace {

void checkOptions(const FlythroughOptions& options) {
    if (options.techniques.empty()) throw std::invalid_argument("flythrough: give at least one technique");
    if (options.runs < 1 || options.warmupRuns < 0)
        throw std::invalid_argument("flythrough: runs must be >= 1, warm-up runs >= 0");
    if (options.frames < 0 || options.frames > kMaxPathFrames)
        throw std::invalid_argument("flythrough: frames must be in 1.." + std::to_string(kMaxPathFrames));
    if (!(options.stableTolerance >= 0.0f && options.stableTolerance <= 1.0f))
        throw std::invalid_argument("flythrough: the stable-reference tolerance must be in [0, 1]");
    if (options.overrides.eye || options.overrides.target || options.overrides.lightPosition)
        throw std::invalid_argument("flythrough: the path places the camera and the light; give no eye, target or light position");
    for (const Technique* technique : options.techniques) {
        if (technique->output != TechniqueOutput::Visibility)
            throw std::invalid_argument("flythrough: " + technique->name +
                                        " produces a shaded image, not V; flicker is measured on V");
    }
}

CameraPath loadPath(const FlythroughOptions& options, const Scene& scene) {
    if (!options.pathFile.empty()) return parseCameraPathCsv(readWholeFile(options.pathFile), options.pathFile, scene.lights);
    if (scene.flythrough.keyframes.empty())
        throw std::invalid_argument("scene " + scene.name + " has no \"flythrough\" path: give --path KEYFRAMES.csv "
                                    "(docs/flythrough.md)");
    return scene.flythrough;
}

// The previous frame of a series, to measure flicker against.
struct SeriesState {
    const Technique* technique;
    FlythroughSeries series;
    ImageChannels previous;   // scoredImage() of the frame before
    std::filesystem::path framesDir;   // where its frames' PNGs go; empty: nowhere
};

// image-NNNN.png and error-NNNN.png of a series' frame, in its own directory.
void writeFrameImages(const std::filesystem::path& framesDir, const FlythroughSeries& series, int frame,
                      const ImageChannels& reference, const ImageChannels& scored, const Frame& rendered) {
    std::string name = series.label();
    std::ranges::replace(name, ' ', '_');
    const std::filesystem::path dir = framesDir / name;
    std::filesystem::create_directories(dir);
    char number[16];
    std::snprintf(number, sizeof number, "%04d.png", frame);
    const int w = scored.width, h = scored.height;
    writePng((dir / (std::string("image-") + number)).string(), w, h, toSrgb8Image(rendered.radiance, {0.0f, ToneOperator::Reinhard}));
    writePng((dir / (std::string("error-") + number)).string(), w, h, errorMapImage(reference, scored, rendered.radiance));
}

FlythroughFrame measureFrame(const PreparedScene& prepared, const ImageChannels& reference, const ImageChannels* previousReference,
                             SeriesState& state, const FlythroughOptions& options, const ProgressStage& progress) {
    const FrameSettings settings{options.simd, state.series.settings, {}};
    const TimedFrames timed = timeFrames(prepared, *state.technique, settings, options.warmupRuns, options.runs, progress);
    FlythroughFrame frame;
    frame.medianMs = timed.timing.medianMs;
    frame.minMs = timed.timing.minMs;
    frame.errors = scoreFrame(reference, timed.last);
    ImageChannels scored = scoredImage(timed.last);
    if (!state.framesDir.empty())
        writeFrameImages(state.framesDir, state.series, int(state.series.frames.size()), reference, scored, timed.last);
    if (previousReference)
        frame.flicker = flickerFigures(*previousReference, reference, state.previous, scored, channel::V, options.stableTolerance);
    state.previous = std::move(scored);
    return frame;
}

}  // namespace

std::string flythroughFileStem(const std::string& scene, const std::vector<const Technique*>& techniques) {
    std::string names;
    for (const Technique* t : techniques) names += (names.empty() ? "" : "+") + t->name;
    return scene + "-flythrough-" + names;
}

std::string FlythroughSeries::label() const {
    std::string text = technique;
    for (const auto& [name, value] : settings) text += " " + name + "=" + value;
    return text;
}

PathFigures pathFigures(const FlythroughSeries& series) {
    PathFigures figures;
    std::vector<double> ms;
    double changeSum = 0.0, stable = 0.0, p99Sum = 0.0;
    int pairs = 0;
    for (const FlythroughFrame& frame : series.frames) {
        ms.push_back(frame.medianMs);
        figures.meanRms += frame.errors.rms / double(series.frames.size());
        figures.meanMisclassifiedPercent +=
            frame.errors.percentOfPixels(frame.errors.misclassified()) / double(series.frames.size());
        if (!frame.flicker) continue;
        changeSum += frame.flicker->mean * double(frame.flicker->stablePixels);
        stable += double(frame.flicker->stablePixels);
        p99Sum += frame.flicker->p99;
        ++pairs;
    }
    figures.medianMs = ms.empty() ? 0.0 : summarizeTimes(ms).medianMs;
    figures.flickerMean = stable > 0.0 ? changeSum / stable : 0.0;
    figures.flickerP99 = pairs > 0 ? p99Sum / pairs : 0.0;
    return figures;
}

FlythroughResults runFlythrough(const FlythroughOptions& options) {
    checkOptions(options);
    const std::vector<SweepPlan> plans = planSweep(options.techniques, options.axes);
    Scene scene = loadScene(options.scene);
    applyOverrides(scene, options.overrides);
    const CameraPath path = loadPath(options, scene);
    const Camera baseCamera = scene.camera;
    const std::vector<Light> baseLights = scene.lights;
    PreparedScene prepared(std::move(scene));

    FlythroughResults results;
    results.scene = prepared.scene().name;
    results.path = options.pathFile.empty() ? "scene" : options.pathFile;
    results.frames = options.frames ? options.frames : path.frames ? path.frames : kDefaultPathFrames;
    results.threads = options.threads ? options.threads : tbb::info::default_concurrency();
    results.warmupRuns = options.warmupRuns;
    results.runs = options.runs;
    results.stableTolerance = options.stableTolerance;
    // Every frame's camera first: an undefined view half way fails before the long part.
    std::vector<PathSample> samples;
    for (int f = 0; f < results.frames; ++f) {
        samples.push_back(samplePath(path, f, results.frames));
        Camera camera = baseCamera;
        std::vector<Light> lights = baseLights;
        placeOnPath(samples.back(), f, camera, lights);
    }
    checkSettings(prepared, plans, options.simd, options.progress, "flythrough");

    const std::filesystem::path framesDir =
        options.imagesDir.empty() ? std::filesystem::path()
                                  : std::filesystem::path(options.imagesDir) /
                                        (flythroughFileStem(results.scene, options.techniques) + "-frames");
    std::vector<SeriesState> states;
    for (const SweepPlan& plan : plans)
        for (const PlannedSetting& setting : plan.settings)
            states.push_back({plan.technique, {plan.technique->name, plan.technique->referenceName, setting.params, {}}, {},
                              framesDir});
    const ProgressStage progress(options.progress, "flythrough: frame",
                                 uint64_t(results.frames) * states.size() * uint64_t(options.warmupRuns + options.runs));
    std::map<std::string, ImageChannels> previousReferences;
    for (int f = 0; f < results.frames; ++f) {
        Camera camera = baseCamera;
        std::vector<Light> lights = baseLights;
        placeOnPath(samples[f], f, camera, lights);
        prepared.setCamera(camera);
        prepared.setLights(lights);
        std::map<std::string, ImageChannels> references;
        withThreads(results.threads, [&] {
            for (SeriesState& state : states) {
                const std::string& name = state.series.reference;
                if (!references.contains(name)) references.emplace(name, renderReferenceImage(prepared, options.simd, name));
                const auto previous = previousReferences.find(name);
                FlythroughFrame frame = measureFrame(prepared, references.at(name),
                                                     previous == previousReferences.end() ? nullptr : &previous->second,
                                                     state, options, progress);
                frame.frame = f;
                frame.time = samples[f].time;
                frame.eye = samples[f].eye;
                frame.target = samples[f].target;
                frame.light = samples[f].light;
                state.series.frames.push_back(std::move(frame));
            }
        });
        previousReferences = std::move(references);
    }
    for (SeriesState& state : states) results.series.push_back(std::move(state.series));
    return results;
}

}  // namespace shadowlab
