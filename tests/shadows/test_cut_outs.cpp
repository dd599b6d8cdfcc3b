// Cut-outs (foliage cards) in every family (docs/cut-outs.md): the camera sees through their
// holes; depth maps and planar shadows follow the texture; the irregular z-buffer tests the
// alpha where each shadow ray meets a card, as the reference does; a shadow volume cannot
// follow a texture and casts the whole card or nothing (fins, which hang their penumbrae on
// the texture's outline, are tested in tests/shadows/fins/test_cut_out_outline.cpp). On the
// foliage case and on mask-card, whose alpha sits at and around its cutoff as a glTF MASK
// material's would; and on a glTF card whose sampler repeats and mirrors its texture, each
// path's holes where a hand computation of the wrap puts them.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <stb_image_write.h>

#include "frame/registry.h"
#include "frame/render.h"
#include "scenes/gltf_scene.h"
#include "scenes/scene_file.h"
#include "tests/scenes/gltf_test_files.h"
#include "tests/scenes/scene_test_files.h"

using namespace shadowlab;

namespace {

std::string sceneFile(const std::string& name) { return std::string(SHADOWLAB_SOURCE_DIR) + "/assets/scenes/" + name; }

struct CutOutCase {
    PreparedScene prepared;
    GBuffer gbuffer;
    std::vector<float> reference;

    CutOutCase(const std::string& name, int width, int height, const std::string& referenceName = "reference",
               std::map<std::string, std::string> referenceParams = {})
        : prepared(smaller(name, width, height)) {
        gbuffer = renderGBuffer(prepared.world(), prepared.scene().camera, raster::bestSimdLevel());
        reference = run(referenceName, std::move(referenceParams));
    }
    static Scene smaller(const std::string& name, int width, int height) {
        Scene scene = loadScene(sceneFile(name));
        scene.camera.width = width, scene.camera.height = height;
        return scene;
    }
    std::vector<float> run(const std::string& technique, std::map<std::string, std::string> given = {}) const {
        const Technique& t = findTechnique(technique);
        const TechniqueParams params(t.name, t.params, given);
        return t.run({.prepared = prepared,
                      .gbuffer = gbuffer,
                      .light = prepared.scene().lights[0],
                      .simd = raster::bestSimdLevel(),
                      .params = params}).visibility;
    }
    size_t hitPixels() const {
        size_t hit = 0;
        for (uint8_t h : gbuffer.hit) hit += h;
        return hit;
    }
    // Hit pixels whose V differs from the reference's by more than 0.5.
    size_t misclassified(const std::vector<float>& V) const {
        size_t wrong = 0;
        for (size_t k = 0; k < V.size(); ++k) wrong += gbuffer.hit[k] && std::abs(V[k] - reference[k]) > 0.5f;
        return wrong;
    }
    double misclassifiedPercent(const std::vector<float>& V) const { return 100.0 * double(misclassified(V)) / double(hitPixels()); }
    double rms(const std::vector<float>& V) const {
        double sum = 0.0;
        for (size_t k = 0; k < V.size(); ++k) {
            if (gbuffer.hit[k]) sum += double(V[k] - reference[k]) * double(V[k] - reference[k]);
        }
        return std::sqrt(sum / double(hitPixels()));
    }
};

const CutOutCase& foliage() {
    static const CutOutCase c("volumetric/foliage-cards.json", 320, 200);
    return c;
}
const CutOutCase& maskCard() {
    static const CutOutCase c("volumetric/mask-card.json", 320, 200);
    return c;
}

}  // namespace

TEST_CASE("the camera sees the ground through the holes of the cards") {
    const WorldGeometry& world = foliage().prepared.world();
    const GBuffer& g = foliage().gbuffer;
    size_t onCards = 0, onGround = 0;
    for (size_t k = 0; k < g.pixelCount(); ++k) {
        if (!g.hit[k]) continue;
        (world.triangleCutOut[g.triangle[k]] >= 0 ? onCards : onGround)++;
    }
    // Nine 0.8 m cards; the leaves fill about 30% of a card (scripts/make_leaf_texture.py).
    REQUIRE(onCards > 1000);
    CHECK(onGround > 20 * onCards);
}

TEST_CASE("depth maps cast the leaves' shape") {
    CHECK(foliage().misclassifiedPercent(foliage().run("shadow-map")) < 0.5);
    CHECK(foliage().misclassifiedPercent(foliage().run("csm")) < 0.5);
}

// The irregular z-buffer asks the reference's question of every receiver, the alpha test
// included (the same texel rule and cutoff, CasterTransmission::solidAt); a pixel may differ
// only where a ray meets a card within float rounding of a texel's or a triangle's edge
// (Embree's float barycentrics against ours, rounded from double), none here. Treating the
// cards as solid misclassifies about 18% of the foliage's pixels.
TEST_CASE("izb equals the reference on cut-outs") {
    for (const CutOutCase* c : {&foliage(), &maskCard()}) {
        CHECK(c->misclassified(c->run("izb")) <= 2);
    }
}

// The planar projection is projective, so a projected card's texture coordinates
// interpolate as on the card and its shadow follows the texture; only rasterization on the
// plane against the reference's rays differs, on a few boundary pixels (2 of 177,311 at
// 640 x 400). Solid cards: 9.4%.
TEST_CASE("planar shadows follow the cut-outs' texture") {
    for (const CutOutCase* c : {&foliage(), &maskCard()}) {
        CHECK(c->misclassifiedPercent(c->run("planar")) < 0.05);
    }
}

// A volume per triangle cannot follow a texture: a card casts its whole square or nothing.
// On the foliage (leaves cover less than half the texture) casting nothing is less wrong:
// every pixel of the leaves' shadow is lit, none else is wrong (2.8% at 640 x 400), where
// the squares misclassify 10.6%. The mask card's texture is mostly solid, so its squares
// are cast (2.1%, the checker's holes shadowed; nothing cast: 3.0%), counted by z-fail.
TEST_CASE("shadow volumes cast a cut-out whole or not at all, whichever is less wrong") {
    const CutOutCase& f = foliage();
    const std::vector<float> coverage = f.run("shadow-volume");
    CHECK(coverage == f.run("shadow-volume", {{"cut-outs", "none"}}));
    size_t falseShadow = 0, leafShadow = 0, hit = 0;
    for (size_t k = 0; k < coverage.size(); ++k) {
        if (!f.gbuffer.hit[k]) continue;
        ++hit;
        falseShadow += coverage[k] < 0.5f && f.reference[k] > 0.5f;
        leafShadow += f.reference[k] < 0.5f;
    }
    CHECK(falseShadow == 0);
    CHECK(f.misclassified(coverage) <= leafShadow);
    CHECK(f.misclassifiedPercent(coverage) < 4.0);
    CHECK(f.misclassifiedPercent(f.run("shadow-volume", {{"cut-outs", "solid"}})) > 6.0);

    const CutOutCase& m = maskCard();
    const std::vector<float> maskCoverage = m.run("shadow-volume");
    CHECK(maskCoverage == m.run("shadow-volume", {{"cut-outs", "solid"}}));
    CHECK(m.misclassifiedPercent(maskCoverage) < m.misclassifiedPercent(m.run("shadow-volume", {{"cut-outs", "none"}})));
}

// Fins, smoothies and penumbra maps hang their fins on the cut-outs' outline:
// tests/shadows/fins/test_cut_out_outline.cpp.

// The same cards as a glTF MASK material (meshes/mask_card.gltf, placed by "models"): every
// family sees the cut-out the JSON + OBJ + PNG case gives, bit for bit, under the case's sun
// for the hard families and under a disk light for the soft ones, so each family's bounds
// above hold for glTF cut-outs too.
TEST_CASE("every family gives a glTF MASK material's cards the V of the same cards from JSON, bit for bit") {
    const auto visibility = [](Scene scene, const std::string& technique) {
        const PreparedScene prepared(std::move(scene));
        const GBuffer g = renderGBuffer(prepared.world(), prepared.scene().camera, raster::bestSimdLevel());
        const Technique& t = findTechnique(technique);
        const TechniqueParams params(t.name, t.params, {});
        return t.run({.prepared = prepared, .gbuffer = g, .light = prepared.scene().lights[0],
                      .simd = raster::bestSimdLevel(), .params = params}).visibility;
    };
    Scene fromJson = CutOutCase::smaller("volumetric/mask-card.json", 160, 100);
    Scene fromGltf = CutOutCase::smaller("volumetric/mask-card-gltf.json", 160, 100);
    REQUIRE(std::ranges::count_if(fromGltf.materials, [](const Material& m) { return m.cutOut(); }) > 0);
    for (const char* technique : {"reference", "izb", "planar", "shadow-volume", "shadow-map", "csm"}) {
        CAPTURE(technique);
        const std::vector<float> V = visibility(fromGltf, technique);
        CHECK(V == visibility(fromJson, technique));
        CHECK(std::ranges::count(V, 0.0f) > 0);
    }
    const Light disk{.type = LightType::Disk, .position = {1.5f, 5.0f, 2.0f}, .direction = glm::normalize(glm::vec3(-1.5f, -5.0f, -2.0f)),
                     .radius = 0.4f, .intensity = glm::vec3(1.0f)};
    fromJson.lights = {disk}, fromGltf.lights = {disk};
    for (const char* technique : {"fins", "smoothies", "penumbra-maps", "pcss"}) {
        CAPTURE(technique);
        CHECK(visibility(fromGltf, technique) == visibility(fromJson, technique));
    }
}

namespace {

// A 3 m card at y = 1 over a ground at y = 0, as glTF: the card's texture coordinates are
// its (x, z), in [0, 3]; its 2 x 2 MASK texture is a checker, solid on the diagonal texels;
// its sampler repeats s and mirrors t.
Scene wrappedCard() {
    test::TempDir dir;
    const unsigned char rgba[16] = {9, 9, 9, 255, 9, 9, 9, 0, 9, 9, 9, 0, 9, 9, 9, 255};
    REQUIRE(stbi_write_png(dir.path("checker.png").c_str(), 2, 2, 4, rgba, 8) != 0);
    test::GltfFile file;
    file.json["images"] = {{{"uri", "checker.png"}}};
    file.json["samplers"] = {{{"wrapS", 10497}, {"wrapT", 33648}}};
    file.json["textures"] = {{{"source", 0}, {"sampler", 0}}};
    file.json["materials"] = {{{"alphaMode", "MASK"}, {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}},
                              {{"alphaMode", "OPAQUE"}}};
    const std::vector<uint32_t> quad = {0, 1, 2, 0, 2, 3};
    const int card = file.vec3s({{0, 1, 0}, {0, 1, 3}, {3, 1, 3}, {3, 1, 0}});
    const int uvs = file.vec2s({{0, 0}, {0, 3}, {3, 3}, {3, 0}});
    const int ground = file.vec3s({{-1, 0, -1}, {-1, 0, 4}, {4, 0, 4}, {4, 0, -1}});
    file.node({{"mesh", file.mesh({{"material", 0}, {"indices", file.indices(quad)},
                                   {"attributes", {{"POSITION", card}, {"TEXCOORD_0", uvs}}}})}});
    file.node({{"mesh", file.mesh({{"material", 1}, {"indices", file.indices(quad)}, {"attributes", {{"POSITION", ground}}}})}});
    Scene scene = loadGltfScene(dir.write("card.gltf", file.gltf()));
    scene.camera = {.eye = {1.5f, 8.0f, 1.5f}, .target = {1.5f, 0.0f, 1.5f}, .up = {0.0f, 0.0f, -1.0f},
                    .fovyDeg = 30.0f, .width = 160, .height = 160};
    scene.lights = {Light{.type = LightType::Directional, .direction = {0.0f, 1.0f, 0.0f}}};
    return scene;
}

// By hand, in glTF's coordinates (s right, t down from the image's top): the texel
// column of s repeated, floor(2 frac(s)), and the row of t mirrored, floor(2 m(t)) with
// m(t) = t mod 2 folded onto [0, 1]; solid where column == row. Nullopt within 0.02 of a
// texel's edge (every multiple of 0.5), where rasterization and rays may round apart.
std::optional<bool> wrappedCardSolidAt(float s, float t) {
    const auto nearEdge = [](float c) { return std::abs(c * 2.0f - std::round(c * 2.0f)) < 0.04f; };
    if (nearEdge(s) || nearEdge(t)) return std::nullopt;
    const int column = int(std::floor(2.0f * (s - std::floor(s))));
    const float folded = std::fmod(t, 2.0f) <= 1.0f ? std::fmod(t, 2.0f) : 2.0f - std::fmod(t, 2.0f);
    return column == int(std::floor(2.0f * folded));
}

bool onCard(float x, float z) { return x > 0.02f && x < 2.98f && z > 0.02f && z < 2.98f; }

}  // namespace

TEST_CASE("a glTF card's REPEAT and MIRRORED_REPEAT sampler puts its holes where a hand computation does, in every path") {
    const PreparedScene prepared(wrappedCard());
    const Camera& camera = prepared.scene().camera;
    const GBuffer g = renderGBuffer(prepared.world(), camera, raster::bestSimdLevel());
    const WorldGeometry& world = prepared.world();
    REQUIRE(world.cutOuts.size() == 1);
    CHECK(world.cutOuts[0].wrap.u == TextureWrap::Repeat);
    CHECK(world.cutOuts[0].wrap.v == TextureWrap::MirroredRepeat);
    const auto visibility = [&](const std::string& technique) {
        const Technique& t = findTechnique(technique);
        const TechniqueParams params(t.name, t.params, {});
        return t.run({.prepared = prepared, .gbuffer = g, .light = prepared.scene().lights[0],
                      .simd = raster::bestSimdLevel(), .params = params}).visibility;
    };
    const std::vector<float> reference = visibility("reference");
    const std::vector<float> shadowMap = visibility("shadow-map");
    CHECK(visibility("izb") == reference);
    size_t cardPixels = 0, holePixels = 0, shadowed = 0, lit = 0, mapWrong = 0;
    for (size_t k = 0; k < g.pixelCount(); ++k) {
        if (!g.hit[k]) continue;
        const glm::vec3 p = g.position[k];
        const bool seesCard = world.triangleCutOut[g.triangle[k]] >= 0;
        // The camera pass: where the eye's ray crosses the card's plane, a solid texel stops it.
        const glm::vec3 crossing = camera.eye + (p - camera.eye) * ((camera.eye.y - 1.0f) / (camera.eye.y - p.y));
        if (onCard(crossing.x, crossing.z)) {
            if (const std::optional<bool> solid = wrappedCardSolidAt(crossing.x, crossing.z)) {
                INFO("pixel " << k << " at " << crossing.x << ", " << crossing.z);
                CHECK(seesCard == *solid);
                (seesCard ? cardPixels : holePixels)++;
            }
        }
        // The sun straight above: a ground point is shadowed where the card above it is solid.
        if (seesCard || !onCard(p.x, p.z)) continue;
        if (const std::optional<bool> solid = wrappedCardSolidAt(p.x, p.z)) {
            INFO("ground pixel " << k << " at " << p.x << ", " << p.z);
            CHECK(reference[k] == (*solid ? 0.0f : 1.0f));
            (*solid ? shadowed : lit)++;
            mapWrong += shadowMap[k] != reference[k];
        }
    }
    // Half the card's texels are solid: both kinds well represented.
    CHECK(cardPixels > 2000);
    CHECK(holePixels > 2000);
    CHECK(shadowed > 500);
    CHECK(lit > 500);
    CHECK(mapWrong == 0);
}
