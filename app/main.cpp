// shadowlab: renders, compares and benchmarks shadow techniques (docs/commands.md).
// Every command exits non-zero with a one-line error on bad input, and writes its output
// files whole or not at all.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>

#include <malloc.h>

#include <CLI/CLI.hpp>

#include "app/commands/options.h"
#include "app/common/output_files.h"
#include "app/composite.h"
#include "app/environment.h"
#include "app/measure/bench_passes.h"
#include "app/measure/flythrough.h"
#include "app/measure/flythrough_report.h"
#include "app/measure/scaling.h"
#include "app/measure/sweep.h"
#include "app/measure/sweep_json.h"
#include "app/measure/sweep_merge.h"
#include "app/plots/flythrough_plot.h"
#include "app/plots/scaling_plot.h"
#include "app/plots/sweep_plot.h"
#include "app/report/report_site.h"
#include "frame/frame_images.h"
#include "frame/registry.h"
#include "frame/render.h"
#include "frame/score.h"
#include "frame/score_json.h"
#include "raster/thread_count.h"
#include "scenes/error_text.h"
#include "scenes/obj_writer.h"
#include "scenes/read_file.h"
#include "scenes/scene_file.h"
#include "scenes/scene_limits.h"
#include "scenes/write_file.h"
#include "shading/compare.h"
#include "shading/image_io.h"
#include "shading/tonemap.h"
#include "shadows/debug_buffers.h"
#include "shadows/depth_map.h"
#include "shadows/progress.h"

using namespace shadowlab;

namespace {

// CLI11 answers a mistyped command with "A subcommand is required"; name it instead.
void requireKnownCommand(const CLI::App& app, int argc, char** argv) {
    if (argc < 2 || argv[1][0] == '-') return;
    std::string known;
    for (const CLI::App* command : app.get_subcommands([](const CLI::App*) { return true; })) {
        if (command->get_name() == argv[1]) return;
        known += (known.empty() ? "" : ", ") + command->get_name();
    }
    throw std::invalid_argument("unknown command '" + std::string(argv[1]) + "' (known: " + known + ")");
}

struct RenderArgs {
    std::string scene, technique = "none", png, aov, debugDir, simd = "auto", errorMap, json, reference;
    std::optional<std::string> casterLod;   // given, even empty, or not
    std::vector<std::string> params;
    int threads = 0;
    float exposure = 0.0f;
    SceneOverrides overrides;
    bool progress = false;
};

// The pictures the JSON of --error-map names, relative to it, for `shadowlab report`: the
// -o image, the error map, the technique's debug buffers and the reference's image, written
// here beside the JSON as J-reference-image.png (and J-reference-visibility.png), so that
// the folders of the other pictures get nothing they did not ask for.
FrameImages scoreImages(const RenderArgs& a, const std::string& technique, const Frame& frame, const Frame& referenceFrame) {
    const std::filesystem::path json = a.json, base = json.parent_path();
    const std::string name = json.stem().string() + "-reference";
    const FrameImages reference =
        writeFramePictures(base, base, name, referenceFrame, nullptr, {a.exposure, ToneOperator::Reinhard});
    FrameImages images;
    if (!a.png.empty()) images.image = relativePath(a.png, base);
    images.errorMap = relativePath(a.errorMap, base);
    // The technique's own V beside the reference's, as a sweep's --images shows it.
    if (frame.output == TechniqueOutput::Visibility) {
        const std::filesystem::path visibility = base / (json.stem().string() + "-visibility.png");
        writePng(visibility, frame.gbuffer.width, frame.gbuffer.height, greyImage(frame.shadow.visibility, 0.0f, 1.0f));
        images.visibility = relativePath(visibility, base);
    }
    images.referenceImage = reference.image;
    images.referenceVisibility = reference.visibility;
    if (!a.debugDir.empty()) images.debugBuffers = debugPictures(base, a.debugDir, technique);
    return images;
}

// The technique's frame against the exact reference: the error map, the counts, the JSON.
void writeErrorMap(const RenderArgs& a, const PreparedScene& prepared, const Technique& technique,
                   const FrameSettings& settings, const Frame& frame) {
    const Scene& scene = prepared.scene();
    const std::string& referenceName = a.reference.empty() ? technique.referenceName : a.reference;
    const Frame referenceFrame = renderReferenceFrame(prepared, settings.simd, referenceName, settings.progress);
    const ImageChannels reference = scoredImage(referenceFrame);
    const ImageChannels test = scoredImage(frame);
    const ErrorFigures figures = scoreImage(reference, test, frame.output);
    writePng(a.errorMap, scene.camera.width, scene.camera.height,
             errorMapImage(reference, test, frame.radiance, scoredChannel(frame.output)));
    std::cout << "against " << referenceName << "\n" << formatText(figures) << "error map: " << a.errorMap
              << " (red: false shadow, blue: false light)\n";
    if (a.json.empty()) return;
    const TechniqueParams params(technique.name, technique.params, settings.params);
    writeTextFile(a.json, formatScoreJson(scene.name, technique.name, referenceName, params.values(), frame, figures,
                                          scoreImages(a, technique.name, frame, referenceFrame), a.overrides));
}

void runRender(const RenderArgs& a) {
    if (a.png.empty() && a.aov.empty() && a.errorMap.empty())
        throw std::invalid_argument("render: give -o OUT.png, --aov OUT.exr and/or --error-map OUT.png");
    requireOutputDirectories({&a.png, &a.aov, &a.errorMap, &a.json});
    Scene loaded = loadScene(a.scene);
    applyOverrides(loaded, a.overrides);
    const PreparedScene prepared(std::move(loaded));
    const Technique& technique = findTechnique(a.technique);
    if (!a.reference.empty()) findTechnique(a.reference);   // a typo fails before rendering
    Progress progress(std::cerr);
    FrameSettings settings{raster::parseSimdLevel(a.simd), {}, a.debugDir, progressIfWanted(progress, a.progress)};
    for (const std::string& p : a.params) parseParamAssignment(p, settings.params);
    if (a.casterLod) settings.params["caster-lod"] = *a.casterLod;
    const Frame frame = renderFrame(prepared, technique, settings);
    const Scene& scene = prepared.scene();
    std::printf("%s: %s in %.2f ms\n", scene.name.c_str(), technique.name.c_str(), frame.techniqueMs);
    for (const TechniqueStat& s : frame.shadow.stats) std::printf("  %-28s %.6g\n", s.name.c_str(), s.value);
    for (const TechniqueStat& s : frame.preparation) std::printf("  %-28s %.6g (scene preparation)\n", s.name.c_str(), s.value);
    const int w = scene.camera.width, h = scene.camera.height;
    if (!a.png.empty()) writePng(a.png, w, h, toSrgb8Image(frame.radiance, {a.exposure, ToneOperator::Reinhard}));
    if (!a.aov.empty()) {
        ImageChannels aov;
        aov.width = w, aov.height = h;
        setRadiance(aov, frame.radiance);
        setGBuffer(aov, frame.gbuffer);
        if (frame.output == TechniqueOutput::Visibility) aov.set(channel::V, frame.shadow.visibility);
        if (!frame.shadow.stencil.empty()) aov.set(channel::stencil, frame.shadow.stencil);
        writeExr(a.aov, aov);
    }
    if (!a.errorMap.empty()) writeErrorMap(a, prepared, technique, settings, frame);
}

struct SweepArgs {
    SweepOptions options;
    std::vector<std::string> techniques, params;
    std::string simd = "auto", outDir = "out", plotY = "auto", shard;
    std::optional<std::string> casterLod;   // given, even empty, or not
    bool progress = false, images = false;
};

// The sweep's report: the table on stdout and STEM.csv, .json and .svg in the directory.
void writeSweepReport(const SweepResults& results, const std::filesystem::path& outDir, PlotErrorAxis plotY) {
    requirePlottable(results.rows, plotY);
    std::cout << formatSweepText(results);
    writeCsvJsonSvg(outDir / sweepFileStem(results), formatSweepCsv(results), formatSweepJson(results),
                    formatSweepSvg(results, plotY));
}

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
    writeSweepReport(runSweep(a.options), outputs.folder(), plotY);
    commitAndList(outputs);
}

struct MergeSweepArgs {
    std::vector<std::string> shards;
    std::string outDir = "out", plotY = "auto";
};

void runMergeSweepCommand(const MergeSweepArgs& a) {
    const PlotErrorAxis plotY = parsePlotErrorAxis(a.plotY);
    std::vector<SweepShardFile> files;
    for (const std::string& path : a.shards) {
        SweepResults shard = parseSweepJson(readWholeFile(path), path);
        // The pictures' paths are relative to each shard's JSON; the merged JSON goes to --out.
        const std::filesystem::path directory = std::filesystem::path(path).parent_path();
        for (SweepRow& row : shard.rows) row.images = rebased(row.images, directory, a.outDir);
        files.push_back({path, std::move(shard)});
    }
    const SweepResults merged = mergeSweepShards(files);
    StagedOutputs outputs(a.outDir);
    writeSweepReport(merged, outputs.folder(), plotY);
    commitAndList(outputs);
}

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
         {std::pair{"-time.svg", FlythroughPlot::Time}, {"-error.svg", FlythroughPlot::Error}})
        writeTextFile(stem.string() + suffix, formatFlythroughSvg(results, plot));
    commitAndList(outputs);
}

struct ReportArgs {
    std::vector<std::string> files;
    std::string outDir = "out/report", plotY = "auto";
};

void runReportCommand(const ReportArgs& a) {
    const size_t pages = writeReportSite(a.files, a.outDir, parsePlotErrorAxis(a.plotY));
    std::cout << "wrote " << pages << " pages: " << (std::filesystem::path(a.outDir) / "index.html").string()
              << "\n";
}

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

struct CompareArgs {
    std::string reference, test, channel = "V", heatmap, json;
};

void runCompare(const CompareArgs& a) {
    CompareOptions options;
    options.channel = a.channel;
    requireOutputDirectories({&a.heatmap, &a.json});
    const ImageChannels reference = readExr(a.reference), test = readExr(a.test);
    const ErrorFigures figures = compareImages(reference, test, options);
    std::cout << formatText(figures);
    const std::string heatmap = a.heatmap.empty() ? std::filesystem::path(a.test).replace_extension("").string() + "-diff.png" : a.heatmap;
    writePng(heatmap, reference.width, reference.height, errorHeatMap(reference, test, options));
    std::cout << "heat map: " << heatmap << "\n";
    if (!a.json.empty()) writeTextFile(a.json, formatJson(figures));
}

struct BenchArgs {
    BenchOptions options;
    std::string simd = "auto", json;
    bool progress = false;
};

void runBenchCommand(BenchArgs a) {
    const MeasuringRun run(a.options, a.simd, a.progress);
    requireOutputDirectories({&a.json});   // before the runs, not after them
    const BenchResults results = runBench(a.options);
    std::cout << formatBenchText(results);
    if (!a.json.empty()) writeTextFile(a.json, formatBenchJson(results));
}

void printTechniques() {
    for (const Technique& tech : techniques()) {
        std::printf("%-16s %s\n", tech.name.c_str(), tech.description.c_str());
        for (const ParamSpec& p : tech.params)
            std::printf("    %s=%s  %s\n", p.name.c_str(), p.defaultValue.c_str(), paramHelp(p).c_str());
    }
}

struct ExportArgs {
    std::string scene, path;
};

void addRenderCommand(CLI::App& app, RenderArgs& a) {
    CLI::App* r = app.add_subcommand("render", "render a scene with a shadow technique");
    r->add_option("scene", a.scene, "built-in scene name or scene file (.json)")->required();
    r->add_option("--technique", a.technique, "shadow technique (see `shadowlab techniques`)")->capture_default_str();
    r->add_option("-o,--output", a.png, "tone-mapped sRGB PNG to write");
    r->add_option("--aov", a.aov, "OpenEXR file with R G B, P.*, N.*, Ns.*, hit, V, depth (and stencil)");
    addSizeOptions(r, a.overrides);
    r->add_option("--threads", a.threads, "worker threads (0: all cores)")->check(CLI::Range(0, kMaxThreads));
    addSimdOption(r, a.simd);
    addVec3Option(r, "--eye", a.overrides.eye, "camera position, overriding the scene's");
    addVec3Option(r, "--target", a.overrides.target, "point the camera looks at");
    r->add_option("--fovy", a.overrides.fovyDeg, "vertical field of view in degrees");
    addLightOptions(r, a.overrides);
    r->add_option("--param", a.params, "technique setting name=value (repeatable; see `shadowlab techniques`)");
    addOptionalText(r, "--caster-lod", a.casterLod, "share of the casters' triangles kept, 0.001..1: --param caster-lod=R");
    r->add_option("--debug-buffers", a.debugDir, "directory for the technique's intermediate buffers");
    r->add_option("--exposure", a.exposure, "exposure in stops for the PNG")->capture_default_str();
    CLI::Option* errorMap = r->add_option("--error-map", a.errorMap,
        "also render the exact reference; PNG of false shadow (red) and false light (blue) over the dimmed image");
    r->add_option("--json", a.json,
                  "with --error-map: error figures, technique stats, time and the pictures as JSON; writes the "
                  "reference's image (and V) beside it as JSON-STEM-reference-image.png (-visibility.png)")
        ->needs(errorMap);
    r->add_option("--reference", a.reference, "with --error-map: the technique to score against (default: the one the technique names, reference or reference-soft)")->needs(errorMap);
    addProgressFlag(r, a.progress);
    r->callback([&a] { withThreads(a.threads, [&a] { runRender(a); }); });
}

// --out and --plot-y, shared by sweep and merge-sweep, which write the same files.
void addSweepReportOptions(CLI::App* cmd, std::string& outDir, std::string& plotY) {
    cmd->add_option("--out", outDir, "directory for SCENE-TECHNIQUES.csv, .json and .svg")->capture_default_str();
    cmd->add_option("--plot-y", plotY,
                    "plot's error axis: auto (rms if every row is scored against a soft reference or on luminance, "
                    "else misclassified), misclassified (%), rms, umbra (umbra errors, %) or rms-display (shaded "
                    "images as displayed)")->capture_default_str();
}

void addSweepCommand(CLI::App& app, SweepArgs& a) {
    CLI::App* s = app.add_subcommand("sweep", "speed against error over a grid of technique settings (CSV, JSON, SVG plot)");
    s->add_option("scene", a.options.scene, "built-in scene name or scene file (.json)")->required();
    s->add_option("--technique", a.techniques, "techniques to compare, comma-separated")->delimiter(',')->required();
    s->add_option("--param", a.params, "one axis: name=v1,v2,... (repeatable; the cross product is run)");
    addOptionalText(s, "--caster-lod", a.casterLod, "caster levels of detail, comma-separated: the axis --param caster-lod=R1,R2,...");
    s->add_option("--threads", a.options.threads, "thread counts, comma-separated (default: all cores)")->delimiter(',')->check(CLI::Range(1, kMaxThreads));
    addTimingOptions(s, "frames per row", a.options.runs, a.options.warmupRuns, a.simd);
    addSweepReportOptions(s, a.outDir, a.plotY);
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
    s->callback([&a] { runSweepCommand(a); });
}

void addMergeSweepCommand(CLI::App& app, MergeSweepArgs& a) {
    CLI::App* m = app.add_subcommand("merge-sweep", "join the JSON files of a sweep's shards (sweep --shard) into the sweep's CSV, JSON and SVG plot");
    m->add_option("shards", a.shards, "the JSON file of every shard, SCENE-TECHNIQUES-shard-I-of-N.json")->required();
    addSweepReportOptions(m, a.outDir, a.plotY);
    m->callback([&a] { runMergeSweepCommand(a); });
}

void addFlythroughCommand(CLI::App& app, FlythroughArgs& a) {
    CLI::App* f = app.add_subcommand("flythrough", "shadows in motion: time, error and flicker of techniques along a "
                                                   "camera (and light) path (CSV, JSON, SVG plots)");
    f->add_option("scene", a.options.scene, "built-in scene name or scene file (.json)")->required();
    f->add_option("--technique", a.techniques, "techniques to run, comma-separated")->delimiter(',')->required();
    f->add_option("--param", a.params, "one axis: name=v1,v2,... (repeatable; the cross product is run)");
    f->add_option("--path", a.options.pathFile, "keyframes as CSV (docs/flythrough.md); default: the scene's "
                                               "\"flythrough\"")->check(CLI::ExistingFile);
    f->add_option("--frames", a.options.frames, "frames sampled along the path (default: the path's, else " +
                  std::to_string(kDefaultPathFrames) + ")")->check(CLI::Range(2, kMaxPathFrames));
    addSizeOptions(f, a.options.overrides);
    f->add_option("--threads", a.options.threads, "worker threads (0: all cores)")
        ->capture_default_str()
        ->check(CLI::Range(0, kMaxThreads));
    addTimingOptions(f, "frames per path frame", a.options.runs, a.options.warmupRuns, a.simd);
    f->add_option("--stable-tolerance", a.options.stableTolerance,
                  "the reference's V counts as unchanged if it moves by at most this")
        ->capture_default_str()
        ->check(CLI::Range(0.0f, 1.0f));
    f->add_option("--out", a.outDir, "directory for SCENE-flythrough-TECHNIQUES.csv, .json, .svg (flicker), "
                                     "-time.svg and -error.svg")->capture_default_str();
    f->add_flag("--images", a.images,
                "also write every frame's image, error map and V, "
                "OUT/SCENE-flythrough-TECHNIQUES-frames/SETTING/NNNN-image.png, -error-map.png, -visibility.png");
    addProgressFlag(f, a.progress);
    f->callback([&a] { runFlythroughCommand(a); });
}

void addReportCommand(CLI::App& app, ReportArgs& a) {
    CLI::App* r = app.add_subcommand("report", "a static HTML site of sweep and render --error-map --json results, "
                                               "read from file:// (index, a page per scene and per setting)");
    r->add_option("files", a.files, "JSON files of sweep (with --images for pictures) or of render --error-map --json")
        ->required();
    r->add_option("--out", a.outDir, "directory for index.html and the rest of the site")->capture_default_str();
    r->add_option("--plot-y", a.plotY, "the plots' error axis, as sweep's --plot-y")->capture_default_str();
    r->callback([&a] { runReportCommand(a); });
}

void addScalingCommand(CLI::App& app, ScalingArgs& a) {
    CLI::App* s = app.add_subcommand("scaling", "time against triangle count over a series of scenes, fitted as t = a + b n (CSV, JSON, SVG)");
    s->add_option("scenes", a.options.scenes, "two or more built-in scene names or scene files (e.g. scenes/scaling/*.json)")->required();
    s->add_option("--technique", a.technique, "the technique to time")->required();
    s->add_option("--param", a.params, "technique setting name=value (repeatable)");
    s->add_option("--threads", a.options.threads, "worker threads (0: all cores)")->capture_default_str()->check(CLI::Range(0, kMaxThreads));
    addTimingOptions(s, "frames per scene", a.options.runs, a.options.warmupRuns, a.simd);
    s->add_option("--out", a.outDir, "directory for scaling-TECHNIQUE.csv, .json and .svg")->capture_default_str();
    addProgressFlag(s, a.progress);
    s->callback([&a] { runScalingCommand(a); });
}

void addCompareCommand(CLI::App& app, CompareArgs& a) {
    CLI::App* c = app.add_subcommand("compare", "error figures of a test image against a reference (conventions.md)");
    c->add_option("reference", a.reference, "reference EXR (its hit channel selects the pixels)")->required()->check(CLI::ExistingFile);
    c->add_option("test", a.test, "EXR to score")->required()->check(CLI::ExistingFile);
    c->add_option("--channel", a.channel, "channel to compare")->capture_default_str();
    c->add_option("--heatmap", a.heatmap, "diff heat-map PNG (default: TEST-diff.png)");
    c->add_option("--json", a.json, "also write the figures as JSON");
    c->callback([&a] { runCompare(a); });
}

void addBenchCommand(CLI::App& app, BenchArgs& a) {
    CLI::App* b = app.add_subcommand("bench", "time depth-only passes and reference rays on the built-in scenes");
    b->add_option("--scenes", a.options.scenes, "scenes to measure")->delimiter(',')->capture_default_str();
    b->add_option("--threads", a.options.threads, "thread counts")->delimiter(',')->capture_default_str()->check(CLI::Range(1, kMaxThreads));
    addTimingOptions(b, "runs per row", a.options.runs, a.options.warmupRuns, a.simd);
    b->add_option("--json", a.json, "also write the rows as JSON");
    addProgressFlag(b, a.progress);
    b->callback([&a] { runBenchCommand(a); });
}

void addEnvironmentCommand(CLI::App& app, EnvironmentArgs& a) {
    CLI::App* e = app.add_subcommand("environment", "an environment map's buffers: SH reconstruction and irradiance, median-cut lights, prefiltered lobes");
    e->add_option("map", a.map, "latitude-longitude map (.exr or .hdr)")->required()->check(CLI::ExistingFile);
    e->add_option("--rotation", a.rotationDegrees, "turn about +Y, degrees (right-handed)")->capture_default_str()->check(CLI::Range(-3600.0, 3600.0));
    e->add_option("--lights", a.lights, "median-cut lights to draw")->capture_default_str()->check(CLI::Range(1, 1 << 20));
    e->add_option("--phong", a.phongShininess, "write the map prefiltered for normalised Phong of this shininess (repeatable)");
    e->add_option("--ggx", a.ggxRoughness, "write the map prefiltered for GGX of this roughness (repeatable), and the split-sum table");
    e->add_option("--sh-window", a.shWindow, "sinc^4 window width against ringing (0: off, else > 2)")->capture_default_str();
    e->add_option("--exposure", a.exposure, "stops for the PNGs")->capture_default_str()->check(CLI::Range(-30.0f, 30.0f));
    e->add_option("--out", a.outDir, "directory for the EXR, PNG and JSON files")->capture_default_str();
    e->callback([&a] { runEnvironmentCommand(a); });
}

void addCompositeCommand(CLI::App& app, CompositeArgs& a) {
    CLI::App* c = app.add_subcommand("composite", "a synthetic object's shadows composited into a photograph (Gibson et al. 2003) and the exact differential reference");
    c->add_option("case", a.scene, "room (slid under the desk), room-lift (raised off the floor), outdoor (the forest panorama) chessboard (a real photograph), or a compositing scene file (.json, docs/scene-format.md); --width and --height apply to the room and outdoor cases")->capture_default_str();
    c->add_option("--passes", a.passes, "shadow passes n per frame; 0: one per occluded source")->delimiter(',')->capture_default_str()->check(CLI::Range(0, 100000));
    c->add_option("--frames", a.frames, "frames of the path (default: all)")->delimiter(',');
    c->add_option("--width", a.width, "image width")->capture_default_str()->check(CLI::Range(16, 4096));
    c->add_option("--height", a.height, "image height")->capture_default_str()->check(CLI::Range(16, 4096));
    c->add_option("--resolution", a.resolution, "texels per side of each cluster's shadow map")->capture_default_str()->check(CLI::Range(kMinMapResolution, kMaxMapResolution));
    c->add_option("--shadow-triangles", a.shadowTriangles, "triangles of the object the maps draw")->capture_default_str()->check(CLI::Range(4, 1 << 24));
    c->add_option("--source-share", a.sourceShare, "share of the radiant power the source set holds")->capture_default_str()->check(CLI::Range(1e-6, 1.0));
    c->add_option("--significance", a.significance, "the shaft hierarchy leaves out less than this share of any vertex's light (the paper's 2% rule)")->capture_default_str()->check(CLI::Range(1e-6, 1.0));
    c->add_option("--reference-strata", a.referenceStrata, "the reference's strata per side of an emitting and of a reflecting patch")->delimiter(',')->expected(2)->capture_default_str()->check(CLI::Range(1, 64));
    c->add_flag("--reference-convergence", a.referenceConvergence, "also render the reference at twice the strata per side and report the RMS between the two");
    c->add_flag("--ldr", a.ldr, "composite the 8-bit photograph with intensity transfers");
    c->add_flag("!--no-reference", a.reference, "skip the exact reference");
    c->add_flag("--masks", a.masks, "write each cluster's mask");
    c->add_flag("--ldr-error", a.ldrError, "also run Figure 3's experiment: the 8-bit path's error against the sources occluded");
    c->add_option("--runs", a.runs, "timed runs per frame (median)")->capture_default_str()->check(CLI::Range(1, 1000));
    c->add_option("--warmup", a.warmupRuns, "untimed runs first")->capture_default_str()->check(CLI::Range(0, 1000));
    c->add_option("--threads", a.threads, "worker threads (0: all cores)")->capture_default_str()->check(CLI::Range(0, kMaxThreads));
    c->add_option("--out", a.outDir, "directory for the images and composite.json")->capture_default_str();
    c->callback([&a] { runCompositeCommand(a); });
}

void addTechniquesCommand(CLI::App& app) {
    app.add_subcommand("techniques", "list the shadow techniques and their parameters")->callback(printTechniques);
}

void addExportObjCommand(CLI::App& app, ExportArgs& a) {
    CLI::App* e = app.add_subcommand("export-obj", "write every triangle of a scene in world space as OBJ");
    e->add_option("scene", a.scene, "built-in scene name or scene file")->required();
    e->add_option("out", a.path, "OBJ file to write")->required();
    e->callback([&a] { writeObj(flatten(loadScene(a.scene)), a.path); });
}

// Frames allocate their buffers afresh (maps, G-buffers, lists: tens of MB each), and a
// fresh page costs a fault and a zero fill, about 5 us per 4 KiB on the VMs we measure on:
// some 20 ms for one 2048^2 map. A renderer keeps such buffers from frame to frame; this
// program gets the same effect by keeping freed memory for reuse: every block comes from
// the heap (no mmap, whose threshold cannot exceed 32 MiB, so the 32 MiB moment maps of
// evsm and msm would be mapped and faulted afresh every frame) and the heap is never
// trimmed, so only the first (warm-up) frame pays the faults. Set once, before any work,
// by the program, not by the library (docs/peers.md, "Measured").
void keepFreedMemoryForReuse() {
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, -1);
    mallopt(M_MMAP_MAX, 0);
}

}  // namespace

int main(int argc, char** argv) {
    keepFreedMemoryForReuse();
    CLI::App app{"shadowlab: a deterministic CPU rasterizer for studying real-time shadows"};
    app.require_subcommand(1);
    // One line whatever the message quotes (scenes/error_text.h).
    app.failure_message([](const CLI::App*, const CLI::Error& e) { return "shadowlab: error: " + oneLine(e.what()) + "\n"; });
    // Each command's callback runs its work during parse(), reading these.
    RenderArgs render;
    SweepArgs sweep;
    MergeSweepArgs mergeSweep;
    ReportArgs report;
    ScalingArgs scaling;
    FlythroughArgs flythrough;
    CompareArgs compare;
    BenchArgs bench;
    ExportArgs exportObj;
    EnvironmentArgs environment;
    CompositeArgs composite;
    addRenderCommand(app, render);
    addSweepCommand(app, sweep);
    addMergeSweepCommand(app, mergeSweep);
    addReportCommand(app, report);
    addScalingCommand(app, scaling);
    addFlythroughCommand(app, flythrough);
    addCompareCommand(app, compare);
    addBenchCommand(app, bench);
    addTechniquesCommand(app);
    addExportObjCommand(app, exportObj);
    addEnvironmentCommand(app, environment);
    addCompositeCommand(app, composite);
    requireFiniteFloats(app);
    try {
        requireKnownCommand(app, argc, argv);
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        return app.exit(error);
    } catch (const std::exception& error) {
        std::cerr << "shadowlab: error: " << oneLine(error.what()) << "\n";
        return 1;
    }
    return 0;
}
