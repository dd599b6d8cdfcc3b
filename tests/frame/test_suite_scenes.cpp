// The benchmark suite's real models (assets/scenes/suite/, docs/performance.md, "Real
// models") that Debian's assimp-testmodels holds: the scene files load the models through
// the glTF path with the triangle counts the docs quote, and the exact reference casts their
// shadow on the ground where the light puts it. The house is the IFC converted by
// scripts/suite_models.sh, which the configure runs (tests/CMakeLists.txt). The grove and
// the dungeon need castle-game-engine-doc, which CI does not install: no test reads them.
#ifdef SHADOWLAB_SUITE_ASSIMP
#include <string>

#include <doctest/doctest.h>

#include "frame/registry.h"
#include "frame/render.h"
#include "scenes/scene_file.h"

using namespace shadowlab;

namespace {

struct SuiteCase {
    const char* file;
    size_t triangles;   // the ground's 8,192 and the model's, as placed
};

// Ground pixels (material 0, the scene file's first) lit and shadowed by the exact reference,
// and where the shadowed ones lie: the model is centred on the origin, so its shadow's
// centroid is on the far side from the light.
void checkShadow(const std::string& file) {
    Scene scene = loadScene(std::string(SHADOWLAB_SOURCE_DIR) + "/assets/scenes/suite/" + file);
    SceneOverrides overrides;
    overrides.width = 160;
    overrides.height = 100;
    applyOverrides(scene, overrides);
    const Light light = scene.lights.at(0);
    const PreparedScene prepared(std::move(scene));
    const Frame frame = renderFrame(prepared, findTechnique("reference"));
    size_t lit = 0, shadowed = 0;
    glm::vec3 shadowSum(0.0f);
    for (size_t k = 0; k < frame.gbuffer.hit.size(); ++k) {
        if (!frame.gbuffer.hit[k] || frame.gbuffer.material[k] != 0) continue;
        if (frame.shadow.visibility[k] == 0.0f) {
            ++shadowed;
            shadowSum += frame.gbuffer.position[k];
        } else {
            ++lit;
        }
    }
    const size_t ground = lit + shadowed;
    INFO(file << ": " << lit << " lit and " << shadowed << " shadowed ground pixels");
    REQUIRE(ground > 0);
    CHECK(shadowed > ground / 50);
    CHECK(lit > ground / 2);
    const glm::vec3 towardsLight = light.type == LightType::Directional ? light.direction : light.position;
    const glm::vec3 centroid = shadowSum / float(shadowed);
    CHECK(centroid.x * towardsLight.x + centroid.z * towardsLight.z < 0.0f);
}

}  // namespace

TEST_CASE("the suite's real models load through the glTF path with the triangle counts docs/performance.md quotes") {
    for (const SuiteCase& c : {SuiteCase{"engine.json", 8192 + 121496}, SuiteCase{"house.json", 8192 + 35906}}) {
        INFO(std::string(c.file));
        const PreparedScene prepared(loadScene(std::string(SHADOWLAB_SOURCE_DIR) + "/assets/scenes/suite/" + c.file));
        CHECK(prepared.world().triangles.size() == c.triangles);
    }
}

TEST_CASE("the exact reference shadows the suite's engine and house on their ground, away from the light") {
    checkShadow("engine.json");
    checkShadow("house.json");
}
#endif
