// Shared by the soft-shadow tests: a scene with its G-buffer and the exact soft reference
// (ReferenceVisibility of the disk light itself: by default 32 x 32 = 1024 stratified
// samples per pixel), and the error figures against it.
#pragma once

#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "frame/registry.h"
#include "frame/render.h"
#include "scenes/scene_file.h"
#include "shadows/reference/reference.h"
#include "shadows/technique.h"
#include "tests/frame/technique_scenes.h"   // smallScene

namespace shadowlab::test {

struct SoftScene {
    PreparedScene prepared;
    const Scene& scene;
    const WorldGeometry& world;
    GBuffer gbuffer;
    CasterTransmission transmission;   // the reference's: cut-outs' holes, translucent casters
    std::vector<float> reference;   // soft V of the area light

    explicit SoftScene(Scene s, int samplesPerAxis = 32)
        : prepared(std::move(s)), scene(prepared.scene()), world(prepared.world()), gbuffer(renderGBuffer(world, scene.camera, raster::bestSimdLevel())),
          transmission(scene, world),
          reference(ReferenceVisibility(world, &transmission).visibility(gbuffer, scene.lights[0], {.areaSamplesPerAxis = samplesPerAxis})) {}

    // With `debugDir`, the technique's intermediate buffers are written there.
    ShadowOutputs run(const std::string& technique, const std::map<std::string, std::string>& given = {},
                      const std::filesystem::path& debugDir = {}) const {
        const Technique& t = findTechnique(technique);
        const TechniqueParams params(t.name, t.params, given);
        return t.run({.prepared = prepared,
                      .gbuffer = gbuffer,
                      .light = scene.lights[0],
                      .simd = raster::bestSimdLevel(),
                      .params = params,
                      .debugDir = debugDir});
    }

    double rms(const std::vector<float>& v) const {
        double sum = 0.0;
        size_t n = 0;
        for (size_t k = 0; k < v.size(); ++k) {
            if (!gbuffer.hit[k]) continue;
            const double e = double(v[k]) - double(reference[k]);
            sum += e * e, ++n;
        }
        return std::sqrt(sum / double(n));
    }
};

// A case of assets/scenes/soft by name, as a path from the source tree (ctest runs in the build tree).
inline std::string softCase(const std::string& name) {
    return std::string(SHADOWLAB_SOURCE_DIR) + "/assets/scenes/soft/" + name + ".json";
}

}  // namespace shadowlab::test
