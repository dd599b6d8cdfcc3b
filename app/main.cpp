// shadowlab: renders, compares and benchmarks shadow techniques (README, "Commands").
// Every command exits non-zero with a one-line error on bad input, and writes its output
// files whole or not at all.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <initializer_list>
#include <iostream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>

#include <CLI/CLI.hpp>

#include "app/bench_passes.h"
#include "frame/render.h"
#include "app/scaling.h"
#include "app/scaling_plot.h"
#include "frame/score.h"
#include "app/sweep.h"
#include "app/sweep_plot.h"
#include "raster/thread_count.h"
#include "scenes/obj_writer.h"
#include "scenes/scene_file.h"
#include "shading/compare.h"
#include "shading/image_io.h"
#include "shading/tonemap.h"

using namespace shadowlab;

namespace {

// "x,y,z" -> vec3; CLI11 reports the message on failure.
std::string parseVec3(const std::string& text, glm::vec3& out) {
    std::istringstream in(text);
    char comma1 = 0, comma2 = 0;
    if (!(in >> out.x >> comma1 >> out.y >> comma2 >> out.z) || comma1 != ',' || comma2 != ',' || !in.eof()) {
        return "expected three numbers as x,y,z, got '" + text + "'";
    }
    if (!std::isfinite(out.x) || !std::isfinite(out.y) || !std::isfinite(out.z)) return "values must be finite";
    return {};
}

void addVec3Option(CLI::App* cmd, const std::string& name, std::optional<glm::vec3>& target, const std::string& help) {
    cmd->add_option_function<std::string>(name, [&target, name](const std::string& text) {
        glm::vec3 v;
        if (const std::string error = parseVec3(text, v); !error.empty()) throw CLI::ValidationError(name, error);
        target = v;
    }, help)->type_name("X,Y,Z");
}

// --light-pos and --light-radius, shared by render and sweep; applyOverrides() checks them.
void addLightOptions(CLI::App* cmd, SceneOverrides& overrides) {
    addVec3Option(cmd, "--light-pos", overrides.lightPosition, "position (centre) of the scene's first light");
    cmd->add_option("--light-radius", overrides.lightRadius, "radius of the scene's first light, which must be a disk (m, > 0)");
}

// A command's output files are written one after another, each whole or not at all; so
// that a later one cannot fail after the earlier ones were written, every destination's
// directory is checked before any work is done (a path naming a directory fails too).
void requireOutputDirectories(std::initializer_list<const std::string*> paths) {
    for (const std::string* path : paths) {
        if (path->empty()) continue;
        const std::filesystem::path directory = std::filesystem::path(*path).parent_path();
        if (!std::filesystem::is_directory(directory.empty() ? "." : directory))
            throw std::runtime_error("cannot write '" + *path + "': no directory '" + directory.string() + "'");
        if (std::filesystem::is_directory(*path)) throw std::runtime_error("cannot write '" + *path + "': it is a directory");
    }
}

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
    std::vector<std::string> params;
    int threads = 0;
    float exposure = 0.0f;
    SceneOverrides overrides;
};

// The technique's frame against the exact reference: the error map, the counts, the JSON.
void writeErrorMap(const RenderArgs& a, const PreparedScene& prepared, const Technique& technique,
                   const FrameSettings& settings, const Frame& frame) {
    const Scene& scene = prepared.scene();
    const std::string& referenceName = a.reference.empty() ? technique.referenceName : a.reference;
    const ImageChannels reference = renderReferenceImage(prepared, settings.simd, referenceName);
    const ImageChannels test = scoredImage(frame);
    const ErrorFigures figures = scoreFrame(reference, frame);
    writePng(a.errorMap, scene.camera.width, scene.camera.height,
             errorMapImage(reference, test, frame.radiance, scoredChannel(frame.output)));
    std::cout << "against " << referenceName << "\n" << formatText(figures) << "error map: " << a.errorMap
              << " (red: false shadow, blue: false light)\n";
    if (a.json.empty()) return;
    const TechniqueParams params(technique.name, technique.params, settings.params);
    writeTextFile(a.json, formatScoreJson(scene.name, technique.name, referenceName, params.values(), frame, figures));
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
    FrameSettings settings{raster::parseSimdLevel(a.simd), {}, a.debugDir};
    for (const std::string& p : a.params) parseParamAssignment(p, settings.params);
    const Frame frame = renderFrame(prepared, technique, settings);
    const Scene& scene = prepared.scene();
    std::printf("%s: %s in %.2f ms\n", scene.name.c_str(), technique.name.c_str(), frame.techniqueMs);
    for (const TechniqueStat& s : frame.shadow.stats) std::printf("  %-28s %.6g\n", s.name.c_str(), s.value);
    const int w = scene.camera.width, h = scene.camera.height;
    if (!a.png.empty()) writePng(a.png, w, h, toSrgb8Image(frame.radiance, {a.exposure, ToneOperator::Reinhard}));
    if (!a.aov.empty()) {
        ImageChannels aov;
        aov.width = w, aov.height = h;
        setRadiance(aov, frame.radiance);
        setGBuffer(aov, frame.gbuffer);
        aov.set(channel::V, frame.shadow.visibility);
        if (!frame.shadow.stencil.empty()) aov.set(channel::stencil, frame.shadow.stencil);
        writeExr(a.aov, aov);
    }
    if (!a.errorMap.empty()) writeErrorMap(a, prepared, technique, settings, frame);
}

// The three files of a sweep or scaling report: STEM.csv, STEM.json and STEM.svg.
void writeReport(const std::filesystem::path& stem, const std::string& csv, const std::string& json, const std::string& svg) {
    for (const auto& [extension, text] : {std::pair{".csv", &csv}, {".json", &json}, {".svg", &svg}}) {
        writeTextFile(stem.string() + extension, *text);
        std::cout << "wrote " << stem.string() + extension << "\n";
    }
}

struct SweepArgs {
    SweepOptions options;
    std::vector<std::string> techniques, params;
    std::string simd = "auto", outDir = "out", plotY = "misclassified";
};

void runSweepCommand(SweepArgs a) {
    for (const std::string& name : a.techniques) a.options.techniques.push_back(&findTechnique(name));
    for (const std::string& p : a.params) a.options.axes.push_back(parseSweepAxis(p));
    a.options.simd = raster::parseSimdLevel(a.simd);
    const PlotErrorAxis plotY = parsePlotErrorAxis(a.plotY);
    std::filesystem::create_directories(a.outDir);   // before the long part, so that it fails early
    const SweepResults results = runSweep(a.options);
    std::cout << formatSweepText(results);
    writeReport(std::filesystem::path(a.outDir) / sweepFileStem(results), formatSweepCsv(results), formatSweepJson(results),
                formatSweepSvg(results, plotY));
}

struct ScalingArgs {
    ScalingOptions options;
    std::string technique, simd = "auto", outDir = "out";
    std::vector<std::string> params;
};

void runScalingCommand(ScalingArgs a) {
    a.options.technique = &findTechnique(a.technique);
    for (const std::string& p : a.params) parseParamAssignment(p, a.options.params);
    a.options.simd = raster::parseSimdLevel(a.simd);
    std::filesystem::create_directories(a.outDir);   // before the long part, so that it fails early
    const ScalingResults results = runScaling(a.options);
    std::cout << formatScalingText(results);
    writeReport(std::filesystem::path(a.outDir) / scalingFileStem(results), formatScalingCsv(results),
                formatScalingJson(results), formatScalingSvg(results));
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

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"shadowlab: a deterministic CPU rasterizer for studying real-time shadows"};
    app.require_subcommand(1);
    app.failure_message([](const CLI::App*, const CLI::Error& e) { return "shadowlab: error: " + std::string(e.what()) + "\n"; });

    RenderArgs render;
    CLI::App* r = app.add_subcommand("render", "render a scene with a shadow technique");
    r->add_option("scene", render.scene, "built-in scene name or scene file (.json)")->required();
    r->add_option("--technique", render.technique, "shadow technique (see `shadowlab techniques`)")->capture_default_str();
    r->add_option("-o,--output", render.png, "tone-mapped sRGB PNG to write");
    r->add_option("--aov", render.aov, "OpenEXR file with R G B, P.*, N.*, hit, V, depth (and stencil)");
    r->add_option("--width", render.overrides.width, "image width in pixels")->check(CLI::Range(1, raster::kMaxViewport));
    r->add_option("--height", render.overrides.height, "image height in pixels")->check(CLI::Range(1, raster::kMaxViewport));
    r->add_option("--threads", render.threads, "worker threads (0: all cores)")->check(CLI::NonNegativeNumber);
    r->add_option("--simd", render.simd, "scalar, avx2, avx512 or auto")->capture_default_str();
    addVec3Option(r, "--eye", render.overrides.eye, "camera position, overriding the scene's");
    addVec3Option(r, "--target", render.overrides.target, "point the camera looks at");
    r->add_option("--fovy", render.overrides.fovyDeg, "vertical field of view in degrees");
    addLightOptions(r, render.overrides);
    r->add_option("--param", render.params, "technique setting name=value (repeatable; see `shadowlab techniques`)");
    r->add_option("--debug-buffers", render.debugDir, "directory for the technique's intermediate buffers");
    r->add_option("--exposure", render.exposure, "exposure in stops for the PNG")->capture_default_str();
    CLI::Option* errorMap = r->add_option("--error-map", render.errorMap,
        "also render the exact reference; PNG of false shadow (red) and false light (blue) over the dimmed image");
    r->add_option("--json", render.json, "with --error-map: error figures, technique stats and time as JSON")->needs(errorMap);
    r->add_option("--reference", render.reference, "with --error-map: the technique to score against (default: the one the technique names, reference or reference-soft)")->needs(errorMap);
    r->callback([&] { withThreads(render.threads, [&] { runRender(render); }); });

    SweepArgs sweep;
    CLI::App* s = app.add_subcommand("sweep", "speed against error over a grid of technique settings (CSV, JSON, SVG plot)");
    s->add_option("scene", sweep.options.scene, "built-in scene name or scene file (.json)")->required();
    s->add_option("--technique", sweep.techniques, "techniques to compare, comma-separated")->delimiter(',')->required();
    s->add_option("--param", sweep.params, "one axis: name=v1,v2,... (repeatable; the cross product is run)");
    s->add_option("--threads", sweep.options.threads, "thread counts, comma-separated (default: all cores)")->delimiter(',')->check(CLI::Range(1, 1024));
    s->add_option("--runs", sweep.options.runs, "measured frames per row")->capture_default_str()->check(CLI::Range(1, 10000));
    s->add_option("--warmup", sweep.options.warmupRuns, "warm-up frames per row")->capture_default_str()->check(CLI::Range(0, 1000));
    s->add_option("--simd", sweep.simd, "scalar, avx2, avx512 or auto")->capture_default_str();
    s->add_option("--out", sweep.outDir, "directory for SCENE-TECHNIQUES.csv, .json and .svg")->capture_default_str();
    s->add_option("--plot-y", sweep.plotY, "plot's error axis: misclassified (%), rms or umbra (umbra errors, %)")->capture_default_str();
    addLightOptions(s, sweep.options.overrides);
    s->add_option("--reference", sweep.options.reference, "score every technique against this one (default: each against the one it names, reference or reference-soft)");
    s->callback([&] { runSweepCommand(sweep); });

    ScalingArgs scaling;
    CLI::App* sc = app.add_subcommand("scaling", "time against triangle count over a series of scenes, fitted as t = a + b n (CSV, JSON, SVG)");
    sc->add_option("scenes", scaling.options.scenes, "two or more built-in scene names or scene files (e.g. scenes/scaling/*.json)")->required();
    sc->add_option("--technique", scaling.technique, "the technique to time")->required();
    sc->add_option("--param", scaling.params, "technique setting name=value (repeatable)");
    sc->add_option("--threads", scaling.options.threads, "worker threads (0: all cores)")->capture_default_str()->check(CLI::Range(0, 1024));
    sc->add_option("--runs", scaling.options.runs, "measured frames per scene")->capture_default_str()->check(CLI::Range(1, 10000));
    sc->add_option("--warmup", scaling.options.warmupRuns, "warm-up frames per scene")->capture_default_str()->check(CLI::Range(0, 1000));
    sc->add_option("--simd", scaling.simd, "scalar, avx2, avx512 or auto")->capture_default_str();
    sc->add_option("--out", scaling.outDir, "directory for scaling-TECHNIQUE.csv, .json and .svg")->capture_default_str();
    sc->callback([&] { runScalingCommand(scaling); });

    CompareArgs compare;
    CLI::App* c = app.add_subcommand("compare", "error figures of a test image against a reference (conventions.md)");
    c->add_option("reference", compare.reference, "reference EXR (its hit channel selects the pixels)")->required()->check(CLI::ExistingFile);
    c->add_option("test", compare.test, "EXR to score")->required()->check(CLI::ExistingFile);
    c->add_option("--channel", compare.channel, "channel to compare")->capture_default_str();
    c->add_option("--heatmap", compare.heatmap, "diff heat-map PNG (default: TEST-diff.png)");
    c->add_option("--json", compare.json, "also write the figures as JSON");
    c->callback([&] { runCompare(compare); });

    BenchOptions bench;
    std::string benchJson, benchSimd = "auto";
    CLI::App* b = app.add_subcommand("bench", "time depth-only passes and reference rays on the built-in scenes");
    b->add_option("--scenes", bench.scenes, "scenes to measure")->delimiter(',')->capture_default_str();
    b->add_option("--threads", bench.threads, "thread counts")->delimiter(',')->capture_default_str()->check(CLI::PositiveNumber);
    b->add_option("--runs", bench.runs, "measured runs per row")->capture_default_str()->check(CLI::Range(1, 10000));
    b->add_option("--warmup", bench.warmupRuns, "warm-up runs per row")->capture_default_str()->check(CLI::Range(0, 1000));
    b->add_option("--simd", benchSimd, "scalar, avx2, avx512 or auto")->capture_default_str();
    b->add_option("--json", benchJson, "also write the rows as JSON");
    b->callback([&] {
        bench.simd = raster::parseSimdLevel(benchSimd);
        const BenchResults results = runBench(bench);
        std::cout << formatBenchText(results);
        if (!benchJson.empty()) writeTextFile(benchJson, formatBenchJson(results));
    });

    CLI::App* t = app.add_subcommand("techniques", "list the shadow techniques and their parameters");
    t->callback([] {
        for (const Technique& tech : techniques()) {
            std::printf("%-16s %s\n", tech.name.c_str(), tech.description.c_str());
            for (const ParamSpec& p : tech.params) {
                std::printf("    %s=%s  %s\n", p.name.c_str(), p.defaultValue.c_str(), paramHelp(p).c_str());
            }
        }
    });

    std::string exportScene, exportPath;
    CLI::App* e = app.add_subcommand("export-obj", "write every triangle of a scene in world space as OBJ");
    e->add_option("scene", exportScene, "built-in scene name or scene file")->required();
    e->add_option("out", exportPath, "OBJ file to write")->required();
    e->callback([&] { writeObj(flatten(loadScene(exportScene)), exportPath); });

    try {
        requireKnownCommand(app, argc, argv);
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        return app.exit(error);
    } catch (const std::exception& error) {
        std::cerr << "shadowlab: error: " << error.what() << "\n";
        return 1;
    }
    return 0;
}
