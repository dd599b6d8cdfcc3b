// One frame: the camera pass (visibility buffer), the G-buffer, the shadow technique's
// visibility V of every light (or of one selected light), and shading that sums them
// (docs/many-lights.md). Used by `shadowlab render`, the golden tests and the bench.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "raster/tile_kernels.h"
#include "scenes/prepared_scene.h"
#include "scenes/scene.h"
#include "shading/gbuffer.h"
#include "shadows/camera_pass.h"
#include "shadows/technique.h"

namespace shadowlab {

// Command-line overrides of the scene's camera and lights. The light overrides
// (lightPosition, lightRadius) act on the first light: the selected one where `light` is
// given.
struct SceneOverrides {
    // `--light N`: the scene keeps scene.lights[N] alone, so that a frame shows that light's
    // shadow exactly as a scene with one light would; applied first, so the light overrides
    // below act on it. None: every light (docs/many-lights.md).
    std::optional<int> light;
    std::optional<int> width, height;
    std::optional<glm::vec3> eye, target, lightPosition;
    std::optional<float> fovyDeg;
    std::optional<float> lightRadius;   // the first light's disk radius, m
};

// Applies the overrides; throws std::invalid_argument for a light index outside the
// scene's lights, a size outside 1..8192, a fovy outside (0, 180), a non-finite vector, an eye equal to the target or a viewing direction
// parallel to the camera's up (the scene file's rule, viewFrameProblem), or a light radius
// that is not > 0 (and finite) or whose first light is not a disk, or a light position for
// a directional first light (which has none).
void applyOverrides(Scene& scene, const SceneOverrides& overrides);

// One light's pass of a frame: the technique run with ShadowInputs::light that light.
struct LightPass {
    size_t light = 0;           // index in scene.lights
    ShadowOutputs shadow;       // its V (and stencil, coloured V) and its stats
    double techniqueMs = 0.0;   // wall time of the technique for this light
};

struct Frame {
    GBuffer gbuffer;
    // With one pass, that pass's outputs (a copy of passes[0].shadow), as a single-light
    // frame always had them. With several, the first pass's buffers, and as stats every
    // pass's, named lightK_NAME for scene.lights[K], with lightK_technique_ms its time
    // (docs/many-lights.md); read passes for the others' V.
    ShadowOutputs shadow;
    // Every light of the scene, in the order of scene.lights (`--light N` leaves the scene
    // one, SceneOverrides::light). A radiance technique lights the scene itself and runs
    // once: one pass, with light 0 (or no light, for a scene without lights).
    std::vector<LightPass> passes;
    TechniqueOutput output = TechniqueOutput::Visibility;   // the technique's
    std::vector<glm::vec3> radiance;   // linear, row-major: the passes' V shaded, or the technique's own
    double techniqueMs = 0.0;          // wall time of the technique alone, the sum over the passes
    // Scene preparation this frame did (Technique::prepare: the edge adjacency or an
    // environment's tables, on the first frame of a technique that reads them), outside
    // techniqueMs.
    std::vector<TechniqueStat> preparation;
};

// What a sequence of frames of one technique keeps from frame to frame: each light's
// TechniqueHistory (shadows/technique_history.h), the view of the frame before (its camera,
// instances and surfaces, which the next frame's motion vectors point into:
// shading/motion_vectors.h) and how many frames it has seen. It belongs to the first frame's prepared
// scene, technique and settings; a frame of another is a std::logic_error, since its states
// would be read as the wrong ones. A copy is a snapshot (app/common/timing.h).
class FrameHistory {
public:
    // The history of the pass of scene.lights[light], for a frame of `technique` with `params`
    // (the settings as given) over `prepared`.
    TechniqueHistory& pass(const PreparedScene& prepared, const Technique& technique,
                           const std::map<std::string, std::string>& params, size_t light);

    // Frames rendered with this history so far: the next frame's index (ShadowInputs::frameIndex).
    uint64_t frames() const { return frames_; }
    // The view of the last frame rendered; null before the first.
    const PreviousView* previousView() const { return previous_ ? &*previous_ : nullptr; }
    // Called by renderFrame once a frame is done: it becomes the frame before.
    void endFrame(PreviousView view) {
        previous_ = std::move(view);
        ++frames_;
    }

private:
    struct Owner {
        const PreparedScene* prepared;
        std::string technique;
        std::map<std::string, std::string> params;
        bool operator==(const Owner&) const = default;
    };
    std::optional<Owner> owner_;
    std::vector<TechniqueHistory> passes_;
    std::optional<PreviousView> previous_;
    uint64_t frames_ = 0;
};

struct FrameSettings {
    raster::SimdLevel simd = raster::bestSimdLevel();
    std::map<std::string, std::string> params;   // the technique's --param settings
    std::filesystem::path debugDir;              // empty: no intermediate buffers (lightDebugFolder())
    Progress* progress = nullptr;                // passed to the technique (ShadowInputs)
    // The sequence this frame continues (FrameHistory); null: it stands alone. A frame that
    // throws leaves the history unusable (the lights whose passes ran have moved on, the view
    // has not): start a new one.
    FrameHistory* history = nullptr;
};

// In a frame of several lights each light's intermediate buffers go to a folder of its own
// in FrameSettings::debugDir: "lightK" for scene.lights[K]. A frame of one light writes
// them into debugDir itself.
std::string lightDebugFolder(size_t light);

// Throws std::invalid_argument for a parameter the technique does not have, and
// std::logic_error for a radiance technique that returns no radiance image.
Frame renderFrame(const PreparedScene& prepared, const Technique& technique, const FrameSettings& settings = {});

}  // namespace shadowlab
