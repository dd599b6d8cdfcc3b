// `shadowlab scaling`: a technique's time against the triangle count over a series of
// scenes, fitted as t = a + b n (app/measure/scaling.h).
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/commands/commands.h"
#include "app/commands/options.h"
#include "app/common/output_files.h"
#include "app/measure/scaling.h"
#include "app/plots/scaling_plot.h"
#include "frame/registry.h"
#include "raster/thread_count.h"
#include "shadows/technique_params.h"

namespace shadowlab {
namespace {

struct ScalingArgs {
    ScalingOptions options;
    std::string technique, simd = "auto", outDir = "out";
    std::vector<std::string> params;
    bool progress = false;
};

void runScalingCommand(ScalingArgs a) {
    a.options.technique = &findTechnique(a.technique);
    for (const std::string& p : a.params) parseParamAssignment(p, a.options.params);
    const MeasuringRun run(a.options, a.simd, a.progress);
    StagedOutputs outputs(a.outDir);   // before the long part, so that it fails early
    const ScalingResults results = runScaling(a.options);
    std::cout << formatScalingText(results);
    writeCsvJsonSvg(outputs.folder() / scalingFileStem(results), formatScalingCsv(results),
                    formatScalingJson(results), formatScalingSvg(results));
    commitAndList(outputs);
}

}  // namespace

void addScalingCommand(CLI::App& command) {
    ScalingArgs& a = argumentsRunBy<ScalingArgs>(command, runScalingCommand);
    CLI::App* s = command.description("time against triangle count over a series of scenes, fitted as t = a + b n (CSV, JSON, SVG)");
    s->add_option("scenes", a.options.scenes, "two or more built-in scene names or scene files (e.g. assets/scenes/scaling/*.json)")->required();
    s->add_option("--technique", a.technique, "the technique to time")->required();
    s->add_option("--param", a.params, "technique setting name=value (repeatable)");
    s->add_option("--threads", a.options.threads, "worker threads (0: all cores)")->capture_default_str()->check(CLI::Range(0, kMaxThreads));
    addTimingOptions(s, "frames per scene", a.options.runs, a.options.warmupRuns, a.simd);
    s->add_option("--out", a.outDir, "directory for scaling-TECHNIQUE.csv, .json and .svg")->capture_default_str();
    addProgressFlag(s, a.progress);
}

}  // namespace shadowlab
