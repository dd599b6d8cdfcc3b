// The Technique interface as the frame pipeline uses it: stat names follow the documented
// rule, a view with no surface is V = 0 for every technique, scene preparation is reported
// once and outside the technique's time, and a radiance technique is shaded and scored by
// its own image.
#include <doctest/doctest.h>

#include <map>
#include <regex>
#include <set>
#include <string>

#include "frame/registry.h"
#include "frame/render.h"
#include "frame/score.h"
#include "scenes/scene_file.h"
#include "tests/frame/technique_scenes.h"

using namespace shadowlab;

using test::runsOnASun;
using test::quickSettings;
using test::smallScene;
using test::skyScene;
using test::sunScene;

TEST_CASE("every technique's stat names are snake_case and end in a unit (docs/architecture.md)") {
    const std::regex rule("[a-z][a-z0-9]*(_[a-z0-9]+)*_(ms|m|texels|pixels|triangles|edges|fragments|fragments_per_pixel|"
                          "texels_per_pixel|per_pixel|receivers|pages|percent|count|flag|ratio|radiance|bytes)");
    const test::TechniqueScenes scenes;
    std::set<std::string> seen;
    for (const Technique& t : techniques()) {
        FrameSettings settings;
        settings.params = quickSettings(t);
        const Frame frame = renderFrame(scenes.sceneFor(t), t, settings);
        int stageLaps = 0;
        for (const TechniqueStat& s : frame.shadow.stats) {
            INFO(t.name << ": " << s.name);
            CHECK(std::regex_match(s.name, rule));
            seen.insert(s.name);
            stageLaps += s.name.ends_with("_ms");
        }
        for (const TechniqueStat& s : frame.preparation) CHECK(std::regex_match(s.name, rule));
        // Every technique but `none` says where its frame goes: two stages at least.
        INFO(t.name);
        CHECK(stageLaps >= (t.name == "none" ? 0 : 2));
    }
    // The stage timer's laps are among them, one per stage of the timed techniques.
    for (const char* stage : {"traversal_ms", "stencil_ms", "illuminance_ms", "penumbra_maps_ms", "lookup_ms",
                              "fill_fragments_per_pixel"})
        CHECK(seen.count(stage) == 1);
}

TEST_CASE("a view that sees no surface gives V = 0 (or no radiance) everywhere for every technique") {
    Scene looksUp = smallScene("sphere-box"), sunUp = smallScene(sunScene()), skyUp = smallScene(skyScene());
    for (Scene* s : {&looksUp, &sunUp, &skyUp}) s->camera.target = s->camera.eye + glm::vec3(0.0f, 1.0f, 0.01f);
    const PreparedScene disk(looksUp), sun(sunUp), sky(skyUp);
    for (const Technique& t : techniques()) {
        INFO(t.name);
        if (t.output == TechniqueOutput::Radiance) {   // no surface, no light reflected
            FrameSettings settings;
            settings.params = quickSettings(t);
            const Frame frame = renderFrame(sky, t, settings);
            CHECK(std::count(frame.radiance.begin(), frame.radiance.end(), glm::vec3(0.0f)) == long(frame.gbuffer.pixelCount()));
            continue;
        }
        const Frame frame = renderFrame(runsOnASun(t) ? sun : disk, t);
        REQUIRE(frame.shadow.visibility.size() == frame.gbuffer.pixelCount());
        CHECK(std::count(frame.gbuffer.hit.begin(), frame.gbuffer.hit.end(), 1) == 0);
        CHECK(std::count(frame.shadow.visibility.begin(), frame.shadow.visibility.end(), 0.0f) ==
              long(frame.gbuffer.pixelCount()));
    }
    // The settings and the light are still checked: an empty view hides no error.
    CHECK_THROWS_WITH_AS(renderFrame(sun, findTechnique("fins")), "fins: needs a disk light", std::invalid_argument);
    for (const char* soft : {"pcss", "vsm", "msm", "multi-sample"}) {
        CHECK_THROWS_WITH_AS(renderFrame(sun, findTechnique(soft)), (std::string(soft) + ": needs an area light (disk or rectangle)").c_str(),
                             std::invalid_argument);
    }
    FrameSettings notSquare;
    notSquare.params = {{"samples", "5"}};
    CHECK_THROWS_AS(renderFrame(disk, findTechnique("multi-sample"), notSquare), std::invalid_argument);
}

TEST_CASE("the edge adjacency is built before the technique's time, once per prepared scene, and reported there") {
    const PreparedScene prepared(smallScene("sphere-box"));
    const Technique& volumes = findTechnique("shadow-volume");
    REQUIRE(volumes.prepare);
    CHECK_FALSE(findTechnique("shadow-map").prepare);
    const Frame first = renderFrame(prepared, volumes), second = renderFrame(prepared, volumes);
    REQUIRE(first.preparation.size() == 1);
    CHECK(first.preparation[0].name == "edge_adjacency_ms");
    CHECK(second.preparation.empty());
    CHECK(first.shadow.visibility == second.shadow.visibility);
}

TEST_CASE("a radiance technique's image is the frame's, scored on its luminance against a radiance reference") {
    const PreparedScene prepared(smallScene("sphere-box"));
    // A technique that lights every surface with a constant radiance c.
    const auto constantRadiance = [](float c) {
        Technique t{"constant", "a test technique: radiance c on every surface", {},
                    [c](const ShadowInputs& in) {
                        ShadowOutputs out;
                        out.radiance.assign(in.gbuffer.pixelCount(), glm::vec3(0.0f));
                        for (size_t k = 0; k < out.radiance.size(); ++k)
                            if (in.gbuffer.hit[k]) out.radiance[k] = glm::vec3(c);
                        return out;
                    },
                    "constant", TechniqueOutput::Radiance};
        return t;
    };
    const Frame reference = renderFrame(prepared, constantRadiance(0.5f));
    const Frame brighter = renderFrame(prepared, constantRadiance(0.75f));
    CHECK(reference.radiance == reference.shadow.radiance);   // not shaded again
    const ImageChannels scored = scoredImage(reference);
    CHECK(scored.find(channel::V) == nullptr);
    REQUIRE(scored.find(channel::Y) != nullptr);
    CHECK(scoreFrame(scored, reference).rms == 0.0);
    CHECK(scoreFrame(scored, brighter).rms == doctest::Approx(0.25).epsilon(1e-6));   // luminance of (0.25, 0.25, 0.25)
    // After Reinhard's c / (1 + Y), for greys Y / (1 + Y): 0.75 / 1.75 - 0.5 / 1.5 = 2 / 21.
    REQUIRE(scoreFrame(scored, brighter).rmsDisplay.has_value());
    CHECK(*scoreFrame(scored, brighter).rmsDisplay == doctest::Approx(2.0 / 21.0).epsilon(1e-5));
    // scoreImage() of an image the caller already has gives the same figures, to the bit.
    const ErrorFigures fromImage = scoreImage(scored, scoredImage(brighter), brighter.output);
    CHECK(fromImage.rms == scoreFrame(scored, brighter).rms);
    CHECK(fromImage.rmsDisplay == scoreFrame(scored, brighter).rmsDisplay);
    CHECK_THROWS_AS(scoreImage(scored, scoredImage(brighter), TechniqueOutput::Visibility), std::invalid_argument);
    CHECK_FALSE(scoreFrame(scoredImage(renderFrame(prepared, findTechnique("none"))), renderFrame(prepared, findTechnique("none")))
                    .rmsDisplay.has_value());
    // A radiance frame has no V to score against a visibility reference, and the other way round.
    const Frame shadowMap = renderFrame(prepared, findTechnique("shadow-map"));
    CHECK_THROWS_AS(scoreFrame(scoredImage(shadowMap), brighter), std::invalid_argument);
    CHECK_THROWS_AS(scoreFrame(scored, shadowMap), std::invalid_argument);
    // A radiance technique that returns no image is a bug, not a black frame.
    Technique broken = constantRadiance(1.0f);
    broken.run = [](const ShadowInputs&) { return ShadowOutputs{}; };
    CHECK_THROWS_AS(renderFrame(prepared, broken), std::logic_error);
}
