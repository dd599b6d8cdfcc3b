// The shadow techniques `shadowlab render --technique NAME` can run. Each takes the
// G-buffer of the camera view and the selected light and returns the visibility V of that
// light at every pixel (conventions.md), plus any intermediate buffers it can show.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "raster/tile_kernels.h"
#include "scenes/prepared_scene.h"
#include "scenes/scene.h"
#include "shading/gbuffer.h"
#include "shadows/progress.h"
#include "shadows/technique_params.h"

namespace shadowlab {

struct ShadowInputs {
    const PreparedScene& prepared;         // the scene, its world geometry and mesh data
    const GBuffer& gbuffer;
    const Light& light;                    // the selected light
    raster::SimdLevel simd;
    const TechniqueParams& params;         // the technique's level-of-detail settings
    std::filesystem::path debugDir;        // empty: write no intermediate buffers
    Progress* progress = nullptr;          // where a slow technique reports; null: nowhere

    const Scene& scene() const { return prepared.scene(); }
    const WorldGeometry& world() const { return prepared.world(); }
};

// A named figure a technique reports about its own work (texels, fill, list lengths...).
struct TechniqueStat {
    std::string name;
    double value;
};

struct ShadowOutputs {
    std::vector<float> visibility;         // V per pixel, row-major, 0 where hit = 0
    std::vector<float> stencil;            // per pixel, empty if the technique uses no stencil
    std::vector<TechniqueStat> stats;
};

struct Technique {
    std::string name;
    std::string description;
    std::vector<ParamSpec> params;
    std::function<ShadowOutputs(const ShadowInputs&)> run;
    // The technique whose V this one is scored against (`render --error-map`, `sweep`):
    // `reference`, the hard shadow of the light's centre, for hard-shadow techniques;
    // `reference-soft`, the visible fraction of an area light, for soft-shadow ones.
    std::string referenceName = "reference";
};

const std::vector<Technique>& techniques();
// Throws std::invalid_argument naming the known techniques.
const Technique& findTechnique(const std::string& name);

// Hard-shadow techniques see a light as a point: an area light's centre stands in for it.
// The result is for visibility only (its intensity keeps the area light's units).
Light pointLightFor(const Light& light);

}  // namespace shadowlab
