// `shadowlab render`: one frame of a scene with a shadow technique, as PNG and/or EXR, and
// with --error-map the technique scored against its exact reference.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/commands/commands.h"
#include "app/commands/options.h"
#include "app/common/output_files.h"
#include "frame/aov_image.h"
#include "frame/frame_images.h"
#include "frame/registry.h"
#include "frame/render.h"
#include "frame/score.h"
#include "frame/score_json.h"
#include "raster/thread_count.h"
#include "scenes/scene_file.h"
#include "scenes/write_file.h"
#include "shading/compare.h"
#include "shading/image_io.h"
#include "shading/tonemap.h"
#include "shadows/debug_buffers.h"
#include "shadows/progress.h"
#include "shadows/technique_params.h"

namespace shadowlab {
namespace {

struct RenderArgs {
    std::string scene, technique = "none", png, aov, debugDir, simd = "auto", errorMap, json, reference;
    std::optional<std::string> casterLod;   // given, even empty, or not
    std::vector<std::string> params;
    int threads = 0;
    int frames = 1;   // frames of a still view's sequence to render; the last is written (docs/temporal.md)
    float exposure = 0.0f;
    SceneOverrides overrides;
    bool progress = false;
};

// The last of `a.frames` frames of a still view's sequence (frame a.frames - 1, counted from
// 0): the frames before it render with the same history (what a temporal technique
// accumulates, a cache it fills) and write nothing; the last writes the technique's buffers
// and is the one returned.
Frame renderLastFrame(const PreparedScene& prepared, const Technique& technique, const RenderArgs& a,
                      const FrameSettings& settings) {
    if (a.frames == 1) return renderFrame(prepared, technique, settings);
    FrameHistory history;
    FrameSettings sequence = settings;
    sequence.history = &history;
    FrameSettings before = sequence;
    before.debugDir.clear();
    for (int f = 1; f < a.frames; ++f) renderFrame(prepared, technique, before);
    return renderFrame(prepared, technique, sequence);
}

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
        writePng(visibility, frame.gbuffer.width, frame.gbuffer.height, greyImage(meanVisibility(frame), 0.0f, 1.0f));
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
    const ScoredReference scored = scoredReference(referenceFrame);
    const ImageChannels& reference = scored.scored;
    const ImageChannels test = scoredImage(frame);
    const ErrorFigures figures = scoreFrame(scored, test, frame);
    writePng(a.errorMap, scene.camera.width, scene.camera.height,
             errorMapImage(reference, test, frame.radiance, scoredChannel(frame.output)));
    const bool severalLights = frame.passes.size() > 1;
    const std::vector<ErrorFigures> lightFigures = severalLights ? scoreLights(reference, test) : std::vector<ErrorFigures>{};
    std::cout << "against " << referenceName << (severalLights ? ", every light" : "") << "\n" << formatText(figures);
    for (size_t k = 0; k < lightFigures.size(); ++k) {
        std::printf("light %zu: rms %.6g, misclassified %.4g%%\n", k, lightFigures[k].rms,
                    lightFigures[k].pixels ? 100.0 * double(lightFigures[k].misclassified()) / double(lightFigures[k].pixels) : 0.0);
    }
    std::cout << "error map: " << a.errorMap << " (red: false shadow, blue: false light)\n";
    if (a.json.empty()) return;
    const TechniqueParams params(technique.name, technique.params, settings.params);
    writeTextFile(a.json, formatScoreJson(scene.name, technique.name, referenceName, params.values(), frame, figures,
                                          scoreImages(a, technique.name, frame, referenceFrame), a.overrides,
                                          lightFigures));
}

void runRender(const RenderArgs& a) {
    if (a.png.empty() && a.aov.empty() && a.errorMap.empty())
        throw std::invalid_argument("render: give -o OUT.png, --aov OUT.exr and/or --error-map OUT.png");
    requireOutputDirectories({&a.png, &a.aov, &a.errorMap, &a.json});
    Scene loaded = loadScene(a.scene);
    for (const std::string& note : loaded.notes) std::cerr << note << "\n";
    applyOverrides(loaded, a.overrides);
    const PreparedScene prepared(std::move(loaded));
    const Technique& technique = findTechnique(a.technique);
    if (!a.reference.empty()) findTechnique(a.reference);   // a typo fails before rendering
    Progress progress(std::cerr);
    FrameSettings settings{raster::parseSimdLevel(a.simd), {}, a.debugDir, progressIfWanted(progress, a.progress)};
    for (const std::string& p : a.params) parseParamAssignment(p, settings.params);
    if (a.casterLod) settings.params["caster-lod"] = *a.casterLod;
    const Frame frame = renderLastFrame(prepared, technique, a, settings);
    const Scene& scene = prepared.scene();
    std::printf("%s: %s in %.2f ms\n", scene.name.c_str(), technique.name.c_str(), frame.techniqueMs);
    for (const TechniqueStat& s : frame.shadow.stats) std::printf("  %-28s %.6g\n", s.name.c_str(), s.value);
    for (const TechniqueStat& s : frame.preparation) std::printf("  %-28s %.6g (scene preparation)\n", s.name.c_str(), s.value);
    const int w = scene.camera.width, h = scene.camera.height;
    if (!a.png.empty()) writePng(a.png, w, h, toSrgb8Image(frame.radiance, {a.exposure, ToneOperator::Reinhard}));
    if (!a.aov.empty()) writeExr(a.aov, aovImage(frame));
    if (!a.errorMap.empty()) writeErrorMap(a, prepared, technique, settings, frame);
}

}  // namespace

void addRenderCommand(CLI::App& command) {
    RenderArgs& a = argumentsRunBy<RenderArgs>(command, [](const RenderArgs& args) {
        withThreads(args.threads, [&args] { runRender(args); });
    });
    CLI::App* r = command.description("render a scene with a shadow technique");
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
    r->add_option("--frames", a.frames,
                  "render N frames of a still view's sequence with one history and write the last "
                  "(frame N - 1; temporal techniques: docs/temporal.md)")
        ->check(CLI::Range(1, 10000))
        ->capture_default_str();
    r->add_option("--exposure", a.exposure, "exposure in stops for the PNG")->capture_default_str();
    CLI::Option* errorMap = r->add_option("--error-map", a.errorMap,
        "also render the exact reference; PNG of false shadow (red) and false light (blue) over the dimmed image");
    r->add_option("--json", a.json,
                  "with --error-map: error figures, technique stats, time and the pictures as JSON; writes the "
                  "reference's image (and V) beside it as JSON-STEM-reference-image.png (-visibility.png)")
        ->needs(errorMap);
    r->add_option("--reference", a.reference, "with --error-map: the technique to score against (default: the one the technique names, reference or reference-soft)")->needs(errorMap);
    addProgressFlag(r, a.progress);
}

}  // namespace shadowlab
