// `shadowlab flythrough`: shadows in motion along a camera (and light) path
// (app/measure/flythrough.h), written as the table, CSV, JSON and three plots (five for a technique that caches
// pages: its pages drawn and cache hits per frame).
#include <filesystem>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/commands/commands.h"
#include "app/commands/options.h"
#include "app/common/output_files.h"
#include "app/measure/flythrough.h"
#include "app/measure/flythrough_report.h"
#include "app/plots/flythrough_plot.h"
#include "frame/registry.h"
#include "raster/thread_count.h"
#include "scenes/scene_limits.h"
#include "scenes/write_file.h"

namespace shadowlab {
namespace {

struct FlythroughArgs {
    FlythroughOptions options;
    std::vector<std::string> techniques, params;
    std::string simd = "auto", outDir = "out";
    bool images = false, progress = false;
};

void runFlythroughCommand(FlythroughArgs a) {
    for (const std::string& name : a.techniques) a.options.techniques.push_back(&findTechnique(name));
    for (const std::string& p : a.params) a.options.axes.push_back(parseSweepAxis(p));
    const MeasuringRun run(a.options, a.simd, a.progress);
    StagedOutputs outputs(a.outDir);   // before the long part, so that it fails early
    if (a.images) a.options.imagesOutDir = outputs.folder();
    const FlythroughResults results = runFlythrough(a.options);
    std::cout << formatFlythroughText(results);
    const std::filesystem::path stem = outputs.folder() / flythroughFileStem(results.scene, a.options.techniques);
    writeCsvJsonSvg(stem, formatFlythroughCsv(results), formatFlythroughJson(results),
                    formatFlythroughSvg(results, FlythroughPlot::Flicker));
    for (const auto& [suffix, plot] :
         {std::pair{"-time.svg", FlythroughPlot::Time}, {"-error.svg", FlythroughPlot::Error},
          {"-flip.svg", FlythroughPlot::Flip}, {"-pages.svg", FlythroughPlot::DrawnPages},
          {"-hits.svg", FlythroughPlot::CacheHits}})
        if (hasFlythroughPlot(results, plot)) writeTextFile(stem.string() + suffix, formatFlythroughSvg(results, plot));
    commitAndList(outputs);
}

}  // namespace

void addFlythroughCommand(CLI::App& command) {
    FlythroughArgs& a = argumentsRunBy<FlythroughArgs>(command, runFlythroughCommand);
    CLI::App* f = command.description("shadows in motion: time, error and flicker of techniques along a "
                                      "camera (and light) path (CSV, JSON, SVG plots)");
    f->add_option("scene", a.options.scene, "built-in scene name or scene file (.json)")->required();
    f->add_option("--technique", a.techniques, "techniques to run, comma-separated")->delimiter(',')->required();
    f->add_option("--param", a.params, "one axis: name=v1,v2,... (repeatable; the cross product is run)");
    f->add_option("--path", a.options.pathFile, "keyframes as CSV (docs/flythrough.md); default: the scene's "
                                               "\"flythrough\"")->check(CLI::ExistingFile);
    f->add_option("--frames", a.options.frames, "frames sampled along the path (default: the path's, else " +
                  std::to_string(kDefaultPathFrames) + ")")->check(CLI::Range(2, kMaxPathFrames));
    addSizeOptions(f, a.options.overrides);
    addLightSelection(f, a.options.overrides);
    f->add_option("--threads", a.options.threads, "worker threads (0: all cores)")
        ->capture_default_str()
        ->check(CLI::Range(0, kMaxThreads));
    addTimingOptions(f, "frames per path frame", a.options.runs, a.options.warmupRuns, a.simd);
    f->add_option("--stable-tolerance", a.options.stableTolerance,
                  "the reference's V counts as unchanged if it moves by at most this")
        ->capture_default_str()
        ->check(CLI::Range(0.0f, 1.0f));
    f->add_option("--out", a.outDir, "directory for SCENE-flythrough-TECHNIQUES.csv, .json, .svg (flicker), "
                                     "-time.svg, -error.svg, and -pages.svg and -hits.svg for a "
                                     "technique that caches pages")->capture_default_str();
    f->add_flag("--images", a.images,
                "also write every frame's image, error map and V, "
                "OUT/SCENE-flythrough-TECHNIQUES-frames/SETTING/NNNN-image.png, -error-map.png, -visibility.png");
    addProgressFlag(f, a.progress);
}

}  // namespace shadowlab
