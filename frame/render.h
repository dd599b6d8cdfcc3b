// One frame: the camera pass (visibility buffer), the G-buffer, the shadow technique's
// visibility V, and shading. Used by `shadowlab render`, the golden tests and the bench.
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

// Command-line overrides of the scene's camera and first light.
struct SceneOverrides {
    std::optional<int> width, height;
    std::optional<glm::vec3> eye, target, lightPosition;
    std::optional<float> fovyDeg;
    std::optional<float> lightRadius;   // the first light's disk radius, m
};

// Applies the overrides; throws std::invalid_argument for a size outside 1..8192, a fovy
// outside (0, 180), a non-finite vector, an eye equal to the target or a viewing direction
// parallel to the camera's up (the scene file's rule, viewFrameProblem), or a light radius
// that is not > 0 (and finite) or whose first light is not a disk, or a light position for
// a directional first light (which has none).
void applyOverrides(Scene& scene, const SceneOverrides& overrides);

struct Frame {
    GBuffer gbuffer;
    ShadowOutputs shadow;
    TechniqueOutput output = TechniqueOutput::Visibility;   // the technique's
    std::vector<glm::vec3> radiance;   // linear, row-major: V shaded, or the technique's own
    double techniqueMs = 0.0;          // wall time of the technique alone
    // Scene preparation this frame did (Technique::prepare: the edge adjacency or an
    // environment's tables, on the first frame of a technique that reads them), outside
    // techniqueMs.
    std::vector<TechniqueStat> preparation;
};

struct FrameSettings {
    raster::SimdLevel simd = raster::bestSimdLevel();
    std::map<std::string, std::string> params;   // the technique's --param settings
    std::filesystem::path debugDir;              // empty: no intermediate buffers
    Progress* progress = nullptr;                // passed to the technique (ShadowInputs)
};

// Throws std::invalid_argument for a parameter the technique does not have, and
// std::logic_error for a radiance technique that returns no radiance image.
Frame renderFrame(const PreparedScene& prepared, const Technique& technique, const FrameSettings& settings = {});

}  // namespace shadowlab
