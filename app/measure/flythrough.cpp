#include "app/measure/flythrough.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <stdexcept>

#include <tbb/info.h>

#include "app/common/output_files.h"
#include "app/common/text_format.h"
#include "app/common/timing.h"
#include "frame/frame_images.h"
#include "frame/score.h"
#include "raster/thread_count.h"
#include "scenes/camera_path.h"
#include "scenes/read_file.h"
#include "scenes/scene_file.h"
#include "scenes/scene_limits.h"

namespace shadowlab {
namespace {

void checkOptions(const FlythroughOptions& options) {
    if (options.techniques.empty()) throw std::invalid_argument("flythrough: give at least one technique");
    if (options.runs < 1 || options.warmupRuns < 0)
        throw std::invalid_argument("flythrough: runs must be >= 1, warm-up runs >= 0");
    if (options.threads < 0 || options.threads > kMaxThreads)
        throw std::invalid_argument("flythrough: threads must be within 0.." + std::to_string(kMaxThreads) +
                                    " (0: every core), got " + std::to_string(options.threads));
    if (options.frames < 0 || options.frames > kMaxPathFrames)
        throw std::invalid_argument("flythrough: frames must be in 2.." + std::to_string(kMaxPathFrames) +
                                    " (0: the path's own)");
    if (!(options.stableTolerance >= 0.0f && options.stableTolerance <= 1.0f))
        throw std::invalid_argument("flythrough: the stable-reference tolerance must be in [0, 1]");
    if (options.overrides.eye || options.overrides.target || options.overrides.lightPosition)
        throw std::invalid_argument(
            "flythrough: the path places the camera and the light; give no eye, target or light position");
    for (const Technique* technique : options.techniques) {
        if (technique->output != TechniqueOutput::Visibility)
            throw std::invalid_argument("flythrough: " + technique->name +
                                        " produces a shaded image, not V; flicker is measured on V");
    }
}

CameraPath loadPath(const FlythroughOptions& options, const Scene& scene) {
    if (!options.pathFile.empty())
        return parseCameraPathCsv(readWholeFile(options.pathFile, kMaxPathFileBytes), options.pathFile, scene.lights);
    if (scene.flythrough.keyframes.empty())
        throw std::invalid_argument("scene " + scene.name + " has no \"flythrough\" path: give --path KEYFRAMES.csv "
                                    "(docs/flythrough.md)");
    return scene.flythrough;
}

// One technique setting along the path, with its frame before, to measure flicker against.
struct SeriesState {
    const Technique* technique;
    FlythroughSeries series;
    ImageChannels previous;              // scoredImage() of the frame before
    std::filesystem::path picturesDir;   // its frames' NNNN-image.png, ...; empty: none
    FrameHistory history = {};           // what the frames before left the technique (timeFrames)
};

FlythroughFrame measureFrame(const PreparedScene& prepared, const ScoredReference& reference,
                             const ImageChannels* previousReference, SeriesState& state,
                             const FlythroughOptions& options, const ProgressStage& progress) {
    const FrameSettings settings{options.simd, state.series.settings, {}, nullptr, &state.history};
    const TimedFrames timed =
        timeFrames(prepared, *state.technique, settings, options.warmupRuns, options.runs, progress);
    FlythroughFrame frame;
    frame.medianMs = timed.timing.medianMs;
    frame.minMs = timed.timing.minMs;
    ImageChannels scored = scoredImage(timed.last);
    frame.errors = scoreFrame(reference, scored, timed.last);
    frame.stats = timed.last.shadow.stats;
    if (!state.picturesDir.empty()) {
        const std::string number = text::format("%04d", int(state.series.frames.size()));
        writeFramePictures(state.picturesDir, state.picturesDir, number, timed.last, &reference.scored);
    }
    if (previousReference)
        frame.flicker =
            flickerFigures(*previousReference, reference.scored, state.previous, scored, channel::V, options.stableTolerance);
    state.previous = std::move(scored);
    return frame;
}

// A frame of the path: where it is, and the camera and lights placed there.
struct PathFrame {
    PathSample sample;
    Camera camera;
    std::vector<Light> lights;
    bool moved = false;   // anything differs from the frame before (FlythroughFrame::moved)
};

bool samePlace(const PathSample& a, const PathSample& b) {
    if (a.eye != b.eye || a.target != b.target || a.light != b.light || a.placements.size() != b.placements.size())
        return false;
    for (size_t k = 0; k < a.placements.size(); ++k) {
        if (a.placements[k].instance != b.placements[k].instance ||
            a.placements[k].worldFromObject != b.placements[k].worldFromObject)
            return false;
    }
    return true;
}

// Every frame placed before any is rendered: an undefined view half way fails first.
std::vector<PathFrame> placeWholePath(const CameraPath& path, int frames, const Camera& baseCamera,
                                      const std::vector<Light>& baseLights) {
    std::vector<PathFrame> placed;
    for (int f = 0; f < frames; ++f) {
        PathFrame& frame = placed.emplace_back(PathFrame{samplePath(path, f, frames), baseCamera, baseLights});
        placeOnPath(frame.sample, f, frame.camera, frame.lights);
        frame.moved = f > 0 && !samePlace(frame.sample, placed[size_t(f) - 1].sample);
    }
    return placed;
}

std::vector<SeriesState> seriesStates(const std::vector<SweepPlan>& plans, const FlythroughOptions& options,
                                      const std::string& scene) {
    const std::filesystem::path framesDir =
        options.imagesOutDir / (flythroughFileStem(scene, options.techniques) + "-frames");
    std::vector<SeriesState> states;
    for (const SweepPlan& plan : plans) {
        for (const PlannedSetting& setting : plan.settings) {
            const FlythroughSeries series{plan.technique->name, plan.technique->referenceName, setting.params, {}};
            std::string folder = series.label();
            std::ranges::replace(folder, ' ', '_');
            states.push_back({plan.technique, series, {},
                              options.imagesOutDir.empty() ? std::filesystem::path() : framesDir / folder});
        }
    }
    return states;
}

// One frame of the path for every series; each reference rendered once. Returns the
// references, which the next frame's flicker is measured against.
std::map<std::string, ScoredReference> renderPathFrame(const PreparedScene& prepared, const PathFrame& placed, int f,
                                                     const std::map<std::string, ScoredReference>& previousReferences,
                                                     std::vector<SeriesState>& states, const FlythroughOptions& options,
                                                     const ProgressStage& progress) {
    std::map<std::string, ScoredReference> references;
    for (SeriesState& state : states) {
        const std::string& name = state.series.reference;
        if (!references.contains(name))
            references.emplace(name, scoredReference(renderReferenceFrame(prepared, options.simd, name)));
        const auto previous = previousReferences.find(name);
        FlythroughFrame frame = measureFrame(prepared, references.at(name),
                                             previous == previousReferences.end() ? nullptr : &previous->second.scored,
                                             state, options, progress);
        frame.frame = f;
        frame.time = placed.sample.time;
        frame.eye = placed.sample.eye;
        frame.target = placed.sample.target;
        frame.light = placed.sample.light;
        frame.moved = placed.moved;
        state.series.frames.push_back(std::move(frame));
    }
    return references;
}

}  // namespace

std::string flythroughFileStem(const std::string& scene, const std::vector<const Technique*>& techniques) {
    std::vector<std::string> names;
    for (const Technique* t : techniques) names.push_back(t->name);
    return scene + "-flythrough-" + techniqueListStem(names);
}

std::string FlythroughSeries::label() const {
    return settings.empty() ? technique : technique + " " + settingsLabel(settings);
}

namespace {

// PathFigures::settleFrames, settled and ghosting (flythrough.h).
void settleFigures(const std::vector<FlythroughFrame>& frames, PathFigures& figures) {
    const auto lastMove = std::find_if(frames.rbegin(), frames.rend(), [](const FlythroughFrame& f) { return f.moved; });
    if (lastMove == frames.rend()) return;   // never moves
    const size_t first = size_t(frames.rend() - lastMove) - 1;
    if (frames.size() - 1 - first < kSettledFrames) return;   // too few still frames to tell
    // The settled level: the mean RMS of the last frames, steadier than one noisy frame.
    double settled = 0.0;
    for (size_t t = frames.size() - kSettledFrames; t < frames.size(); ++t) settled += frames[t].errors.rms;
    settled /= double(kSettledFrames);
    // 10%: a noisy technique's whole-image RMS moves a few per cent from frame to frame.
    const auto within = [&](const FlythroughFrame& f) { return std::abs(f.errors.rms - settled) <= 0.1 * settled + 1e-4; };
    size_t settledFrom = frames.size();
    while (settledFrom > first && within(frames[settledFrom - 1])) --settledFrom;
    figures.settleFrames = int(settledFrom - first);
    // Settled only if it held the level for longer than the frames that define it.
    figures.settled = settledFrom + kSettledFrames < frames.size();
    double excess = 0.0;
    for (size_t t = first; t < frames.size(); ++t) excess += std::max(0.0, frames[t].errors.rms - settled);
    figures.ghosting = excess;
}

}  // namespace

PathFigures pathFigures(const FlythroughSeries& series) {
    PathFigures figures;
    std::vector<double> ms;
    double changeSum = 0.0, stable = 0.0, p99Sum = 0.0;
    int pairs = 0;
    for (const FlythroughFrame& frame : series.frames) {
        ms.push_back(frame.medianMs);
        figures.meanRms += frame.errors.rms / double(series.frames.size());
        figures.meanFlip += frame.errors.flipMean.value_or(0.0) / double(series.frames.size());
        figures.meanMisclassifiedPercent +=
            frame.errors.percentOfPixels(frame.errors.misclassified()) / double(series.frames.size());
        if (!frame.flicker || frame.flicker->stablePixels == 0) continue;
        changeSum += frame.flicker->mean * double(frame.flicker->stablePixels);
        stable += double(frame.flicker->stablePixels);
        p99Sum += frame.flicker->p99;
        ++pairs;
    }
    figures.medianMs = ms.empty() ? 0.0 : summarizeTimes(ms).medianMs;
    figures.flickerMean = stable > 0.0 ? changeSum / stable : 0.0;
    figures.flickerP99 = pairs > 0 ? p99Sum / pairs : 0.0;
    settleFigures(series.frames, figures);
    return figures;
}

FlythroughResults runFlythrough(const FlythroughOptions& options) {
    checkOptions(options);
    return runFlythrough(loadScene(options.scene), options);
}

FlythroughResults runFlythrough(Scene scene, const FlythroughOptions& options) {
    checkOptions(options);
    const std::vector<SweepPlan> plans = planSweep(options.techniques, options.axes);
    applyOverrides(scene, options.overrides);
    // Flicker is measured on one light's V, and a path moves one light.
    if (scene.lights.size() > 1)
        throw std::invalid_argument("flythrough: the scene has " + std::to_string(scene.lights.size()) +
                                    " lights; flicker is measured on one light's V: give --light N");
    const CameraPath path = loadPath(options, scene);
    const int frames = options.frames ? options.frames : path.frames ? path.frames : kDefaultPathFrames;
    if (frames < 2) throw std::invalid_argument("flythrough: a path needs at least 2 frames; flicker compares each "
                                                "frame with the one before");
    const Camera baseCamera = scene.camera;
    const std::vector<Light> baseLights = scene.lights;
    PreparedScene prepared(std::move(scene));

    FlythroughResults results{prepared.scene().name, options.pathFile.empty() ? "scene" : options.pathFile,
                              frames,
                              options.threads ? options.threads : tbb::info::default_concurrency(),
                              options.warmupRuns, options.runs, options.stableTolerance, {}};
    const std::vector<PathFrame> placed = placeWholePath(path, results.frames, baseCamera, baseLights);
    checkSettings(prepared, plans, options.simd, options.progress, "flythrough");
    std::vector<SeriesState> states = seriesStates(plans, options, results.scene);
    const uint64_t framesToRender =
        uint64_t(results.frames) * states.size() * uint64_t(options.warmupRuns + options.runs);
    const ProgressStage progress(options.progress, "flythrough: frame", framesToRender);
    std::map<std::string, ScoredReference> previousReferences;
    for (int f = 0; f < results.frames; ++f) {
        prepared.setCamera(placed[f].camera);
        prepared.setLights(placed[f].lights);
        // What derives from where they are (the references' BVH) is built again for the frame.
        prepared.setInstanceTransforms(placed[f].sample.placements);
        withThreads(results.threads, [&] {
            previousReferences =
                renderPathFrame(prepared, placed[f], f, previousReferences, states, options, progress);
        });
    }
    for (SeriesState& state : states) results.series.push_back(std::move(state.series));
    return results;
}

}  // namespace shadowlab
