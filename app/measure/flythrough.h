// `shadowlab flythrough`: shadows in motion (docs/flythrough.md). A camera path (and
// optionally the first light's and some instances') is sampled at a number of frames; at every frame each
// technique setting is timed as in `sweep` (warm-up frames, then the median of the measured
// ones), scored against its exact reference of that frame, and its temporal stability
// measured against the frame before (shading/temporal_stability.h): the change of V on the
// pixels where the reference did not change, so that only flicker the reference does not
// have is counted.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "app/measure/sweep_plan.h"
#include "frame/render.h"
#include "raster/rasterizer.h"
#include "shading/compare.h"
#include "shading/temporal_stability.h"
#include "shadows/progress.h"

namespace shadowlab {

inline constexpr int kDefaultPathFrames = 48;

struct FlythroughOptions {
    std::string scene;                       // built-in name or .json path
    SceneOverrides overrides;                // size only: the path moves the camera and light
    std::string pathFile;                    // CSV keyframes; empty: the scene's "flythrough"
    int frames = 0;                          // >= 2; 0: the path's own count, else kDefaultPathFrames
    std::vector<const Technique*> techniques;
    std::vector<SweepAxis> axes;
    int threads = 0;                         // 0: all cores
    int warmupRuns = 1, runs = 3;
    float stableTolerance = kStableReferenceTolerance;
    // Non-empty: the directory the command's files go to; each frame's image, error map and V
    // are written as PNG into DIR/STEM-frames/SERIES/NNNN-image.png, NNNN-error-map.png and
    // NNNN-visibility.png (STEM: flythroughFileStem; SERIES: the label, '_' for spaces), e.g.
    // to make a video.
    std::filesystem::path imagesOutDir;
    raster::SimdLevel simd = raster::bestSimdLevel();
    Progress* progress = nullptr;
};

struct FlythroughFrame {
    int frame = 0;
    double time = 0.0;                       // the path's time of the frame
    glm::vec3 eye{0.0f}, target{0.0f};
    std::optional<glm::vec3> light;          // where the path put the first light, if it moves it
    bool moved = false;                      // the camera, the light or an instance differs from the frame before
    double medianMs = 0.0, minMs = 0.0;
    ErrorFigures errors;
    std::optional<FlickerFigures> flicker;   // against the frame before: none for frame 0
    // The technique's figures for the frame (its last measured run's, stage times the runs'
    // medians): what a technique that keeps state shows about it, a virtual map's pages
    // rendered and cache hits.
    std::vector<TechniqueStat> stats;
};

// One technique setting along the whole path.
struct FlythroughSeries {
    std::string technique, reference;
    std::map<std::string, std::string> settings;   // its axis values (not defaults)
    std::vector<FlythroughFrame> frames;
    std::string label() const;                     // "csm snap=off", or the technique alone
};

// A series' figures over the path: the median of the frames' times, the mean of their RMS,
// FLIP (ErrorFigures::flipMean) and misclassified share, the mean change over every stable pixel of every frame pair (each
// pair weighted by its stable pixels) and the mean of the 99th percentiles of the pairs that
// have stable pixels.
//
// Over a path that ends still (at least kSettledFrames frames after its last move,
// FlythroughFrame::moved), how a technique settles once the motion stops (docs/temporal.md),
// against its settled level, the mean RMS of the path's last kSettledFrames frames:
// settleFrames, the frames after the last move until every later frame's RMS is within 10%
// (and 1e-4) of that level; settled, whether it then held the level for more frames than
// those that define it (false: still converging at the path's end, settleFrames a lower
// bound); and ghosting, the RMS above that level summed over the frames from the last move
// on (RMS x frames: the error a technique's history drags behind the motion). A technique
// without history settles at once (0 frames, ghosting near 0). None on a path that never
// moves or holds still for fewer frames.
inline constexpr size_t kSettledFrames = 4;
struct PathFigures {
    double medianMs = 0.0, meanRms = 0.0, meanFlip = 0.0, meanMisclassifiedPercent = 0.0;
    double flickerMean = 0.0, flickerP99 = 0.0;
    std::optional<int> settleFrames;
    bool settled = false;
    std::optional<double> ghosting;
};
PathFigures pathFigures(const FlythroughSeries& series);

struct FlythroughResults {
    std::string scene, path;                 // path: the CSV file, or "scene" for the scene's own
    int frames = 0, threads = 1, warmupRuns = 0, runs = 0;
    float stableTolerance = 0.0f;
    std::vector<FlythroughSeries> series;    // per technique, its settings in axis order
};

// "<scene>-flythrough-<technique>[+<technique>...]", each technique once, in order: the stem
// of the command's files.
std::string flythroughFileStem(const std::string& scene, const std::vector<const Technique*>& techniques);

// Loads the scene and the path (the CSV, or the scene's own: a scene without one fails),
// checks every technique setting with one frame, then renders the path. Throws
// std::invalid_argument (or SceneError) naming the problem, before the long part where it can.
FlythroughResults runFlythrough(const FlythroughOptions& options);
// The same on a scene already loaded, e.g. one a program built (the Python module's);
// FlythroughOptions::scene is not read.
FlythroughResults runFlythrough(Scene scene, const FlythroughOptions& options);

}  // namespace shadowlab
