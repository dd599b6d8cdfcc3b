// `shadowlab sweep`: speed against error over a grid of technique settings
// (app/measure/sweep.h), whole or as one shard of it.
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/commands/commands.h"
#include "app/commands/options.h"
#include "app/commands/sweep_files.h"
#include "app/common/output_files.h"
#include "app/measure/sweep.h"
#include "app/plots/sweep_plot.h"
#include "frame/registry.h"
#include "raster/thread_count.h"

namespace shadowlab {
namespace {

struct SweepArgs {
    SweepOptions options;
    std::vector<std::string> techniques, params;
    std::string simd = "auto", outDir = "out", plotY = "auto", shard;
    std::optional<std::string> casterLod;   // given, even empty, or not
    bool progress = false, images = false;
};

void runSweepCommand(SweepArgs a) {
    for (const std::string& name : a.techniques) a.options.techniques.push_back(&findTechnique(name));
    for (const std::string& p : a.params) a.options.axes.push_back(parseSweepAxis(p));
    if (a.casterLod) a.options.axes.push_back(parseSweepAxis("caster-lod=" + *a.casterLod));
    const MeasuringRun run(a.options, a.simd, a.progress);
    if (!a.shard.empty()) a.options.shard = parseSweepShard(a.shard);
    const PlotErrorAxis plotY = parsePlotErrorAxis(a.plotY);
    for (const Technique* t : a.options.techniques) {   // before the long part, as below
        if (plotY == PlotErrorAxis::RmsDisplay && t->output != TechniqueOutput::Radiance)
            throw std::invalid_argument("--plot-y rms-display: " + t->name + " is scored on V, which has no displayed luminance");
    }
    StagedOutputs outputs(a.outDir);   // before the long part, so that it fails early
    if (a.images) a.options.imagesOutDir = outputs.folder();
    writeSweepFiles(runSweep(a.options), outputs.folder(), plotY);
    commitAndList(outputs);
}

}  // namespace

void addSweepCommand(CLI::App& command) {
    SweepArgs& a = argumentsRunBy<SweepArgs>(command, runSweepCommand);
    CLI::App* s = command.description("speed against error over a grid of technique settings (CSV, JSON, SVG plot)");
    s->add_option("scene", a.options.scene, "built-in scene name or scene file (.json)")->required();
    s->add_option("--technique", a.techniques, "techniques to compare, comma-separated")->delimiter(',')->required();
    s->add_option("--param", a.params, "one axis: name=v1,v2,... (repeatable; the cross product is run)");
    addOptionalText(s, "--caster-lod", a.casterLod, "caster levels of detail, comma-separated: the axis --param caster-lod=R1,R2,...");
    s->add_option("--threads", a.options.threads, "thread counts, comma-separated (default: all cores)")->delimiter(',')->check(CLI::Range(1, kMaxThreads));
    addTimingOptions(s, "frames per row", a.options.runs, a.options.warmupRuns, a.simd);
    addSweepFileOptions(s, a.outDir, a.plotY);
    addSizeOptions(s, a.options.overrides);
    addLightOptions(s, a.options.overrides);
    s->add_option("--reference", a.options.reference, "score every technique against this one (default: each against the one it names, reference or reference-soft)");
    s->add_option("--shard", a.shard,
                  "run only part I of N: the settings whose index k (from 0, in the sweep's order) has k mod N = I - 1, "
                  "at every thread count; I counts from 1, as SLURM_ARRAY_TASK_ID with --array=1-N. "
                  "Writes SCENE-TECHNIQUES-shard-I-of-N.*; merge-sweep joins the shards")->type_name("I/N");
    s->add_flag("--images", a.images,
                "also write each setting's image, error map, V and debug buffers and each reference's image and V "
                "as PNG into OUT/SCENE-TECHNIQUES-images (for `shadowlab report`)");
    addProgressFlag(s, a.progress);
}

}  // namespace shadowlab
