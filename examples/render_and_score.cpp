// Example 2: render a built-in scene with a shadow technique and score its shadows against
// the exact reference.
//
//   render_and_score OUT.png [SCENE] [TECHNIQUE] [--size W H] [NAME=VALUE ...]
//
// SCENE is a built-in scene's name (default sphere-box) or a .json path, TECHNIQUE one of
// list_techniques' names (default shadow-map), NAME=VALUE sets a technique parameter. Writes
// OUT.png (the shaded image) and OUT-errors.png (red: false shadow, blue: false light) and
// prints the error figures.
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "frame/registry.h"
#include "frame/render.h"
#include "frame/score.h"
#include "scenes/scene_file.h"
#include "shading/tonemap.h"
#include "shadows/technique.h"

using namespace shadowlab;

int main(int argc, char** argv) try {
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s OUT.png [SCENE] [TECHNIQUE] [--size W H] [NAME=VALUE ...]\n", argv[0]);
        return 2;
    }
    const std::filesystem::path out = argv[1];
    std::string sceneName = "sphere-box", techniqueName = "shadow-map";
    int width = 0, height = 0, positional = 0;
    FrameSettings settings;   // SIMD level (the best one), technique parameters, no debug buffers
    for (int k = 2; k < argc; ++k) {
        const std::string arg = argv[k];
        if (arg == "--size") {
            if (k + 2 < argc) width = std::atoi(argv[k + 1]), height = std::atoi(argv[k + 2]), k += 2;
            if (width < 1 || height < 1) throw std::invalid_argument("--size takes a width and a height, both >= 1");
        } else if (arg.find('=') != std::string::npos) parseParamAssignment(arg, settings.params);
        else if (positional++ == 0) sceneName = arg;
        else techniqueName = arg;
    }

    // 1. The scene: meshes, materials, lights and a camera, from a JSON file. A built-in
    //    scene's name is looked up in the installed (or source tree's) scene directory.
    std::printf("built-in scenes: %s\n", builtinSceneDir().c_str());
    Scene loaded = loadScene(sceneName);
    if (width > 0) loaded.camera.width = width, loaded.camera.height = height;
    // Prepared once for any number of frames: every instance's triangles in world space (the
    // one geometry that the rasterizer, the techniques and the ray-traced reference all see)
    // and, when a technique asks, the meshes' edge adjacency.
    const PreparedScene prepared(std::move(loaded));
    const Scene& scene = prepared.scene();

    // 2. The frame. renderFrame() rasterizes the camera view into a G-buffer (per pixel: is
    //    there a surface, its position and normal), runs the technique, which returns the
    //    light's visibility V at every pixel (0 in shadow, 1 lit, in between for soft
    //    shadows), and shades the first light: L = ambient * albedo + V * BRDF * E * cos.
    const Technique& technique = findTechnique(techniqueName);
    const Frame frame = renderFrame(prepared, technique, settings);
    std::printf("%s: %s in %.2f ms (%dx%d)\n", scene.name.c_str(), technique.name.c_str(), frame.techniqueMs,
                scene.camera.width, scene.camera.height);
    for (const TechniqueStat& stat : frame.shadow.stats) std::printf("  %-28s %.6g\n", stat.name.c_str(), stat.value);

    // 3. The reference: the same view's visibility computed exactly, by a shadow ray per pixel
    //    (Embree) to the light's centre, or many rays over an area light for soft shadows.
    const ImageChannels reference = renderReferenceImage(prepared, settings.simd, technique.referenceName);

    // 4. Scoring, over the pixels where the reference sees a surface: the error of V, and
    //    how many pixels are misclassified, shadowed where they should be lit (false shadow:
    //    shadow acne) or lit where they should be shadowed (false light: leaks, peter-panning).
    const ErrorFigures figures = scoreFrame(reference, frame);
    std::printf("against %s\n%s", technique.referenceName.c_str(), formatText(figures).c_str());
    std::printf("misclassified: %.4f %% of %llu pixels\n", figures.percentOfPixels(figures.misclassified()),
                (unsigned long long)figures.pixels);

    // 5. Images for people: the tone-mapped frame, and the error map over it.
    const int w = scene.camera.width, h = scene.camera.height;
    writePng(out, w, h, toSrgb8Image(frame.radiance, {}));
    std::filesystem::path errors = out;
    errors.replace_filename(out.stem().string() + "-errors.png");
    writePng(errors, w, h, errorMapImage(reference, scoredImage(frame), frame.radiance, scoredChannel(frame.output)));
    std::printf("wrote %s and %s\n", out.c_str(), errors.c_str());
    return 0;
} catch (const std::exception& e) {
    std::fprintf(stderr, "render_and_score: %s\n", e.what());
    return 1;
}
