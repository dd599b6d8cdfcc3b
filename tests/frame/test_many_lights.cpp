// Every light of a scene in one frame (docs/many-lights.md): V per light is the technique's V
// for that light alone, the shaded image is the sum of the lights in the scene's order, the
// frame's stats hold each light's, `--light N` is the single-light frame, and the scoring
// over several lights stacks their V.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "frame/registry.h"
#include "frame/render.h"
#include "frame/score.h"
#include "scenes/scene_file.h"
#include "shading/shade.h"
#include "tests/frame/technique_scenes.h"
#include "tests/same_bits.h"

using namespace shadowlab;
using shadowlab::test::sameBytes;
using shadowlab::test::smallScene;

namespace {

const std::string kThreeLights = std::string(SHADOWLAB_SOURCE_DIR) + "/assets/scenes/many-lights/three-lights.json";

Scene withLights(Scene scene, std::vector<Light> lights) {
    scene.lights = std::move(lights);
    return scene;
}

// A scene of two lights of one kind, so that every visibility technique can shadow both:
// sphere-box's disk (the soft techniques need an area light; the hard ones take its
// centre) and a second one, or for the techniques of a sun (test::runsOnASun)
// the sun case's sun and a second one. No ambient term, so that each light alone shades
// exactly its own term (0 + t = t).
struct TwoLights {
    Scene both;
    Light a, b;
    explicit TwoLights(bool suns = false) : both(smallScene(suns ? test::sunScene() : "sphere-box", 80, 50)) {
        both.environment.ambient = glm::vec3(0.0f);
        a = both.lights[0];
        b = a;
        b.position = {-5.0f, 6.0f, 2.0f};
        b.direction = glm::normalize(suns ? b.position : -b.position);
        b.intensity = {2.0f, 1.5f, 1.0f};
        both.lights = {a, b};
    }
};

// Quick settings: small maps, few light samples.
FrameSettings quick(const Technique& technique) {
    FrameSettings settings;
    for (const ParamSpec& p : technique.params) {
        if (p.name == "resolution" && p.type == ParamType::Integer && p.min <= 256) settings.params["resolution"] = "256";
        if (p.name == "samples-per-axis") settings.params[p.name] = "3";
    }
    return settings;
}

SceneOverrides lightAlone(int n) {
    SceneOverrides overrides;
    overrides.light = n;
    return overrides;
}

bool sameRadiance(const std::vector<glm::vec3>& x, const std::vector<glm::vec3>& y) { return sameBytes(x, y); }

}  // namespace

TEST_CASE("many lights: for every visibility technique two lights shade the sum of each alone, each light's V its own") {
    int ran = 0;
    for (const Technique& technique : techniques()) {
        if (technique.output != TechniqueOutput::Visibility) continue;
        CAPTURE(technique.name);
        const TwoLights s(test::runsOnASun(technique));
        const PreparedScene both(s.both), onlyA(withLights(s.both, {s.a})), onlyB(withLights(s.both, {s.b}));
        const FrameSettings settings = quick(technique);
        const Frame a = renderFrame(onlyA, technique, settings), b = renderFrame(onlyB, technique, settings),
                    ab = renderFrame(both, technique, settings);
        REQUIRE(ab.passes.size() == 2);
        CHECK(sameBytes(ab.passes[0].shadow.visibility, a.shadow.visibility));
        CHECK(sameBytes(ab.passes[1].shadow.visibility, b.shadow.visibility));
        std::vector<glm::vec3> sum(a.radiance.size());
        for (size_t k = 0; k < sum.size(); ++k) sum[k] = a.radiance[k] + b.radiance[k];   // (0 + t_a) + t_b
        CHECK(sameRadiance(ab.radiance, sum));
        ++ran;
    }
    CHECK(ran >= 27);   // every visibility technique
}

// A light that reaches no surface in view (below the ground, shining down, so every surface
// seen faces away from it) gives V = 0 everywhere for every visibility technique, rather than
// the error of a light view fitted to no receivers: one such light among many must not stop
// the frame (a glTF file's spot aimed away from the camera's view).
TEST_CASE("many lights: a light that reaches nothing in view gives V = 0 for every visibility technique, and its frame the others' image") {
    Scene base = smallScene("sphere-box", 80, 50);
    base.instances.erase(base.instances.begin() + 1);   // the ground and the box, no sphere
    const Light spot{.type = LightType::Spot, .position = {2.0f, -5.0f, -1.0f}, .direction = {0.0f, -1.0f, 0.0f}};
    const Light disk{.type = LightType::Disk, .position = spot.position, .direction = spot.direction, .radius = 0.5f};
    const Light sun{.type = LightType::Directional, .direction = {0.0f, -1.0f, 0.0f}};
    int ran = 0;
    for (const Technique& technique : techniques()) {
        // `none` is the unshadowed baseline, V = 1 on every surface (shading's cosine darkens them).
        if (technique.output != TechniqueOutput::Visibility || technique.name == "none") continue;
        CAPTURE(technique.name);
        const Light& away = test::runsOnASun(technique) ? sun : technique.referenceName == "reference-soft" ? disk : spot;
        const PreparedScene prepared(withLights(base, {away}));
        const Frame frame = renderFrame(prepared, technique, quick(technique));
        REQUIRE(!anyReachable(frame.gbuffer, away));
        CHECK(std::ranges::count(frame.shadow.visibility, 0.0f) == ptrdiff_t(frame.gbuffer.pixelCount()));
        ++ran;
    }
    CHECK(ran >= 26);
    const Technique& shadowMap = findTechnique("shadow-map");
    const PreparedScene lit(base), withAway(withLights(base, {base.lights[0], spot}));
    CHECK(sameRadiance(renderFrame(withAway, shadowMap).radiance, renderFrame(lit, shadowMap).radiance));
}

TEST_CASE("many lights: each light's stats are in the frame as lightK_NAME and their times sum to the total") {
    const PreparedScene prepared(smallScene(kThreeLights));
    REQUIRE(prepared.scene().lights.size() == 3);
    for (const char* name : {"shadow-map", "shadow-volume", "izb", "reference"}) {
        CAPTURE(name);
        const Frame frame = renderFrame(prepared, findTechnique(name));
        REQUIRE(frame.passes.size() == 3);
        double sum = 0.0;
        for (const LightPass& pass : frame.passes) {
            const std::string prefix = "light" + std::to_string(pass.light) + "_";
            const auto find = [&](const std::string& stat) {
                for (const TechniqueStat& s : frame.shadow.stats) {
                    if (s.name == stat) return std::optional<double>(s.value);
                }
                return std::optional<double>();
            };
            CHECK(find(prefix + "technique_ms") == pass.techniqueMs);
            REQUIRE(!pass.shadow.stats.empty());
            for (const TechniqueStat& s : pass.shadow.stats) CHECK(find(prefix + s.name) == s.value);
            sum += pass.techniqueMs;
        }
        CHECK(test::sameBits(sum, frame.techniqueMs));
    }
}

// csm's cascades are for the sun; its point and spot lights get shadow-map's frame with the
// same map settings, so a mixed scene renders whole.
TEST_CASE("many lights: csm cascades the sun of a mixed scene and gives its point and spot lights shadow-map's V") {
    const PreparedScene prepared(smallScene(kThreeLights));
    const std::vector<Light>& lights = prepared.scene().lights;
    REQUIRE(lights.size() == 3);
    FrameSettings settings;
    settings.params = {{"resolution", "512"}, {"filter", "grid"}, {"grid-size", "3"}};
    const Frame csm = renderFrame(prepared, findTechnique("csm"), settings);
    const Frame map = renderFrame(prepared, findTechnique("shadow-map"), settings);
    REQUIRE(csm.passes.size() == 3);
    const auto stat = [](const LightPass& pass, const std::string& name) {
        for (const TechniqueStat& s : pass.shadow.stats) {
            if (s.name == name) return s.value;
        }
        return -1.0;
    };
    for (size_t k = 0; k < lights.size(); ++k) {
        CAPTURE(k);
        const bool sun = lights[k].type == LightType::Directional;
        CHECK(stat(csm.passes[k], "cascades_count") == (sun ? 4.0 : 0.0));
        CHECK(sameBytes(csm.passes[k].shadow.visibility, map.passes[k].shadow.visibility) == !sun);
    }
}

TEST_CASE("many lights: --light N is the frame of that light alone, and --light 0 of a one-light scene today's frame") {
    const Technique& shadowMap = findTechnique("shadow-map");
    const Scene three = smallScene(kThreeLights);
    const Frame all = renderFrame(PreparedScene(three), shadowMap);
    for (int n = 0; n < 3; ++n) {
        CAPTURE(n);
        Scene selected = three;
        applyOverrides(selected, lightAlone(n));
        REQUIRE(selected.lights.size() == 1);
        const Frame one = renderFrame(PreparedScene(selected), shadowMap);
        REQUIRE(one.passes.size() == 1);
        CHECK(sameBytes(one.shadow.visibility, all.passes[size_t(n)].shadow.visibility));
        // The single-light frame: its light alone shaded, its stats unprefixed.
        CHECK(sameRadiance(one.radiance, shade(selected, one.gbuffer, 0, one.shadow.visibility)));
        CHECK(one.shadow.stats.front().name == "resolution_texels");
    }
    // A scene of one light: --light 0 changes no byte.
    const Scene sphereBox = smallScene("sphere-box");
    Scene zero = sphereBox;
    applyOverrides(zero, lightAlone(0));
    const Frame today = renderFrame(PreparedScene(sphereBox), shadowMap), selected = renderFrame(PreparedScene(zero), shadowMap);
    CHECK(sameBytes(today.shadow.visibility, selected.shadow.visibility));
    CHECK(sameRadiance(today.radiance, selected.radiance));
    // A bad N is named.
    Scene bad = three;
    CHECK_THROWS_WITH_AS(applyOverrides(bad, lightAlone(3)), "--light 3: the scene has 3 lights (indices 0..2)",
                         std::invalid_argument);
    CHECK_THROWS_WITH_AS(applyOverrides(bad, lightAlone(-1)), "--light -1: the scene has 3 lights (indices 0..2)",
                         std::invalid_argument);
}

TEST_CASE("many lights: the references run per light, and a frame is scored per light and over every (pixel, light) pair") {
    const TwoLights s;
    const PreparedScene both(s.both), onlyA(withLights(s.both, {s.a})), onlyB(withLights(s.both, {s.b}));
    for (const char* referenceName : {"reference", "reference-soft"}) {
        CAPTURE(referenceName);
        const ImageChannels reference = renderReferenceImage(both, raster::bestSimdLevel(), referenceName);
        const ImageChannels referenceA = renderReferenceImage(onlyA, raster::bestSimdLevel(), referenceName);
        const ImageChannels referenceB = renderReferenceImage(onlyB, raster::bestSimdLevel(), referenceName);
        REQUIRE(visibilityChannels(reference) == std::vector<std::string>{"light0.V", "light1.V"});
        CHECK(sameBytes(reference.at("light0.V"), referenceA.at("V")));
        CHECK(sameBytes(reference.at("light1.V"), referenceB.at("V")));
    }
    // A technique against the hard reference: each light's figures are those of the light
    // alone; the overall ones weigh every light's hit pixels once.
    const Technique& technique = findTechnique("shadow-map");
    const auto scored = [&](const PreparedScene& p) {
        return std::pair(renderReferenceImage(p, raster::bestSimdLevel()), scoredImage(renderFrame(p, technique)));
    };
    const auto [reference, test] = scored(both);
    const auto [referenceA, testA] = scored(onlyA);
    const auto [referenceB, testB] = scored(onlyB);
    const std::vector<ErrorFigures> perLight = scoreLights(reference, test);
    REQUIRE(perLight.size() == 2);
    const ErrorFigures a = scoreImage(referenceA, testA, TechniqueOutput::Visibility);
    const ErrorFigures b = scoreImage(referenceB, testB, TechniqueOutput::Visibility);
    CHECK(perLight[0].rms == a.rms);
    CHECK(perLight[1].rms == b.rms);
    const ErrorFigures overall = scoreImage(reference, test, TechniqueOutput::Visibility);
    CHECK(overall.pixels == a.pixels + b.pixels);
    CHECK(overall.falseShadow == a.falseShadow + b.falseShadow);
    CHECK(overall.falseLight == a.falseLight + b.falseLight);
    CHECK(overall.rms == doctest::Approx(std::sqrt(0.5 * (a.rms * a.rms + b.rms * b.rms))).epsilon(1e-9));
    CHECK(a.misclassified() + b.misclassified() > 0);   // the figures compared are not all 0
}
