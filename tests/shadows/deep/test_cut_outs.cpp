// Cut-outs (foliage cards) in every pass: the camera sees through their holes, depth maps
// cast leaf-shaped shadows, and a technique that does not draw through the rasterizer's
// depth pass (shadow volumes extrude whole triangles) casts squares, its known limitation.
#include <doctest/doctest.h>

#include <map>

#include "frame/registry.h"
#include "frame/render.h"
#include "frame/score.h"
#include "scenes/scene_file.h"

using namespace shadowlab;

namespace {

struct FoliageCase {
    PreparedScene prepared;
    GBuffer gbuffer;
    std::vector<float> reference;

    FoliageCase() : prepared(smaller()) {
        gbuffer = renderGBuffer(prepared.world(), prepared.scene().camera, raster::bestSimdLevel());
        reference = run("reference");
    }
    static Scene smaller() {
        Scene scene = loadScene(std::string(SHADOWLAB_SOURCE_DIR) + "/assets/scenes/volumetric/foliage-cards.json");
        scene.camera.width = 320, scene.camera.height = 200;
        return scene;
    }
    std::vector<float> run(const std::string& technique) const {
        const Technique& t = findTechnique(technique);
        const TechniqueParams params(t.name, t.params, {});
        return t.run({.prepared = prepared,
                      .gbuffer = gbuffer,
                      .light = prepared.scene().lights[0],
                      .simd = raster::bestSimdLevel(),
                      .params = params}).visibility;
    }
    // The share of hit pixels (in percent) whose V differs from the reference by more than 0.5.
    double misclassifiedPercent(const std::vector<float>& V) const {
        size_t wrong = 0, hit = 0;
        for (size_t k = 0; k < V.size(); ++k) {
            if (!gbuffer.hit[k]) continue;
            ++hit, wrong += std::abs(V[k] - reference[k]) > 0.5f;
        }
        return 100.0 * double(wrong) / double(hit);
    }
};

}  // namespace

TEST_CASE("the camera sees the ground through the holes of the cards") {
    const FoliageCase foliage;
    const WorldGeometry& world = foliage.prepared.world();
    size_t onCards = 0, onGround = 0;
    for (size_t k = 0; k < foliage.gbuffer.pixelCount(); ++k) {
        if (!foliage.gbuffer.hit[k]) continue;
        (world.triangleCutOut[foliage.gbuffer.triangle[k]] >= 0 ? onCards : onGround)++;
    }
    // Nine 0.8 m cards; the leaves fill about 30% of a card (scripts/make_leaf_texture.py).
    REQUIRE(onCards > 1000);
    CHECK(onGround > 20 * onCards);
}

TEST_CASE("depth maps cast the leaves' shape and shadow volumes cast the cards' squares") {
    const FoliageCase foliage;
    CHECK(foliage.misclassifiedPercent(foliage.run("shadow-map")) < 0.5);
    CHECK(foliage.misclassifiedPercent(foliage.run("csm")) < 0.5);
    CHECK(foliage.misclassifiedPercent(foliage.run("shadow-volume")) > 4.0);
}
