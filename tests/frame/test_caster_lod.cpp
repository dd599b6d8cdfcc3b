// Caster level of detail in the frame (frame/render.h, scenes/caster_lod.h): every technique
// but the references takes `caster-lod`, draws the simplified casters and still sees the
// whole receivers; the simplification is scene preparation; at ratio 1 nothing changes.
#include <doctest/doctest.h>

#include <algorithm>
#include <optional>
#include <string>

#include <tbb/global_control.h>

#include "frame/registry.h"
#include "frame/render.h"
#include "frame/score.h"
#include "tests/frame/technique_scenes.h"

using namespace shadowlab;

namespace {

double stat(const std::vector<TechniqueStat>& stats, const std::string& name) {
    const auto s = std::ranges::find(stats, name, &TechniqueStat::name);
    REQUIRE(s != stats.end());
    return s->value;
}

// The technique's frame at its quick settings (technique_scenes.h) or its defaults.
Frame frameAt(const PreparedScene& prepared, const Technique& t, const std::string& casterLod, bool quick = true) {
    FrameSettings settings;
    if (quick) settings.params = test::quickSettings(t);
    if (!casterLod.empty()) settings.params["caster-lod"] = casterLod;
    return renderFrame(prepared, t, settings);
}

const std::vector<float>& scored(const Frame& f) { return f.shadow.visibility; }

}  // namespace

TEST_CASE("caster LOD: every technique but the references and none has it") {
    for (const Technique& t : techniques()) {
        INFO(t.name);
        const bool reference = t.name == "none" || t.name.starts_with("reference");
        CHECK(hasCasterLod(t) == !reference);
    }
}

TEST_CASE("caster LOD: every technique that has it draws the simplified casters and shades the whole receivers") {
    const test::TechniqueScenes scenes(160, 100);
    for (const Technique& t : techniques()) {
        if (!hasCasterLod(t)) continue;
        INFO(t.name);
        const PreparedScene& prepared = scenes.sceneFor(t);
        const Frame whole = frameAt(prepared, t, ""), one = frameAt(prepared, t, "1"), coarse = frameAt(prepared, t, "0.02");
        // Ratio 1 is the scene itself: the same bytes as no setting, nothing prepared for it.
        CHECK(one.shadow.visibility == whole.shadow.visibility);
        CHECK(one.radiance == whole.radiance);
        CHECK(std::ranges::none_of(one.preparation, [](const TechniqueStat& s) { return s.name == "caster_lod_ms"; }));
        CHECK(stat(whole.shadow.stats, "caster_lod_triangles") == double(prepared.world().triangles.size()));
        CHECK(stat(whole.shadow.stats, "caster_lod_error_m") == 0.0);
        // At 2% the casters are coarse polyhedra: the shadows move, the receivers do not.
        CHECK(stat(coarse.shadow.stats, "caster_lod_triangles") < 0.1 * double(prepared.world().triangles.size()));
        CHECK(stat(coarse.shadow.stats, "caster_lod_error_m") > 0.0);
        CHECK(coarse.gbuffer.position == whole.gbuffer.position);
        CHECK(coarse.gbuffer.triangle == whole.gbuffer.triangle);
        if (t.output == TechniqueOutput::Visibility) CHECK(coarse.shadow.visibility != whole.shadow.visibility);
        else CHECK(coarse.radiance != whole.radiance);
    }
}

TEST_CASE("caster LOD: the simplification is scene preparation, once per ratio and prepared scene") {
    const PreparedScene prepared(test::smallScene("sphere-box"));
    const Technique& volumes = findTechnique("shadow-volume");
    const Frame first = frameAt(prepared, volumes, "0.1"), second = frameAt(prepared, volumes, "0.1");
    // The simplified casters get their own edge adjacency, also prepared once.
    CHECK(first.preparation.size() == 2);
    CHECK(stat(first.preparation, "caster_lod_ms") >= 0.0);
    CHECK(stat(first.preparation, "edge_adjacency_ms") >= 0.0);
    CHECK(second.preparation.empty());
    CHECK(second.shadow.visibility == first.shadow.visibility);
    CHECK(frameAt(prepared, volumes, "0.2").preparation.size() == 2);   // another ratio, another copy
    CHECK_THROWS_AS(frameAt(prepared, volumes, "0"), std::invalid_argument);
    CHECK_THROWS_AS(frameAt(prepared, volumes, "1.5"), std::invalid_argument);
}

// Edge collapses keep a subset of a mesh's vertices, so a simplified convex caster lies
// inside the whole one: its depth from the light is never nearer than the surface's, and
// its volume starts behind it. A technique that compared receivers against the coarse
// caster's own depth (the receivers simplified too) would shadow the lit side in patches.
// The terminator's band, where the receivers' lift (liftedReceivers) may turn a point away
// from the light, is left out: cos < 0.1 there.
TEST_CASE("caster LOD: a convex caster simplified inside itself leaves its own lit side lit") {
    const PreparedScene prepared(test::smallScene("sphere-box", 320, 200));
    const uint32_t sphere = 1;   // sphere-box's instances: ground, sphere, box
    REQUIRE(prepared.scene().instances[sphere].name == "sphere");
    for (const char* name : {"shadow-map", "shadow-volume", "izb"}) {
        INFO(name);
        const Technique& t = findTechnique(name);
        const Frame whole = frameAt(prepared, t, "", false), coarse = frameAt(prepared, t, "0.05", false);
        const GBuffer& g = whole.gbuffer;
        size_t litOnSphere = 0, stillLit = 0;
        for (size_t k = 0; k < g.pixelCount(); ++k) {
            if (!g.hit[k] || prepared.world().triangleInstance[g.triangle[k]] != sphere || scored(whole)[k] != 1.0f) continue;
            if (glm::dot(g.normal[k], glm::normalize(prepared.scene().lights[0].position - g.position[k])) < 0.1f) continue;
            ++litOnSphere;
            stillLit += scored(coarse)[k] == 1.0f;
        }
        REQUIRE(litOnSphere > 1000);
        CHECK(stillLit == litOnSphere);
    }
}

TEST_CASE("caster LOD: a technique sees each receiver lifted by its own instance's simplification error") {
    const PreparedScene prepared(test::smallScene("sphere-box", 160, 100));
    std::vector<glm::vec3> seen;
    std::vector<float> lift;
    Technique probe{"probe", "records the G-buffer it is given", {},
                    [&](const ShadowInputs& in) {
                        seen = in.gbuffer.position;
                        lift.assign(in.receiverLiftM.begin(), in.receiverLiftM.end());
                        return unlitOutputs(in.gbuffer);
                    }};
    probe = withCasterLod(probe);
    FrameSettings settings;
    const Frame whole = renderFrame(prepared, probe, settings);
    CHECK(seen == whole.gbuffer.position);
    CHECK(lift.empty());
    settings.params["caster-lod"] = "0.05";
    const Frame coarse = renderFrame(prepared, probe, settings);
    CHECK(coarse.gbuffer.position == whole.gbuffer.position);   // the frame keeps the G-buffer
    REQUIRE(lift.size() == 3);   // ground, sphere, box
    CHECK(lift[0] == 0.0f);      // a flat grid loses no shape
    CHECK(lift[1] > 0.0f);
    CHECK(lift[1] < 0.05f);      // a few centimetres at most on a 1 m sphere
    CHECK(*std::ranges::max_element(lift) == float(stat(coarse.shadow.stats, "caster_lod_error_m")));
    const GBuffer& g = whole.gbuffer;
    size_t sphere = 0;
    for (size_t k = 0; k < g.pixelCount(); ++k) {
        if (!g.hit[k]) continue;
        const uint32_t instance = prepared.world().triangleInstance[g.triangle[k]];
        CHECK(seen[k] == g.position[k] + g.normal[k] * lift[instance]);
        sphere += instance == 1;
    }
    CHECK(sphere > 500);
}

TEST_CASE("caster LOD: the bunny's shadow error grows as its triangles drop, with no acne from its own coarse copy") {
    const PreparedScene prepared(test::smallScene("bunny", 320, 200));
    const ImageChannels reference = renderReferenceImage(prepared, raster::bestSimdLevel(), "reference");
    for (const char* name : {"shadow-volume", "izb"}) {
        const Technique& t = findTechnique(name);
        double previous = -1.0;
        for (const char* lod : {"1", "0.25", "0.05", "0.01"}) {
            INFO(name << " at " << lod);
            const ErrorFigures e = scoreFrame(reference, frameAt(prepared, t, lod, false));
            const double misclassified = 100.0 * double(e.misclassified()) / double(e.pixels);
            CHECK(misclassified >= previous);
            CHECK(misclassified < 0.5);   // % of hit pixels: the outline moves, the shadow stays
            // The whole bunny lies up to about the simplifier's error beneath its coarse
            // copy; unlifted, the exact irregular z-buffer shadowed 0.66% of the pixels there
            // at 0.25 (640 x 400).
            CHECK(100.0 * double(e.falseShadow) / double(e.pixels) < 0.05);
            previous = misclassified;
        }
        CHECK(previous > 0.02);   // at 1% of the triangles the outline has moved visibly
    }
}

TEST_CASE("caster LOD: the same bytes for 1 and 2 threads and every SIMD level, simplification included") {
    const test::TechniqueScenes scenes(160, 100);
    for (const char* name : {"shadow-map", "shadow-volume", "izb", "fins", "env-subtractive"}) {
        const Technique& t = findTechnique(name);
        std::optional<Frame> first;
        for (int threads : {1, 2}) {
            const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
            // A prepared scene of its own, so that the simplification runs under this count too.
            const PreparedScene prepared(scenes.sceneFor(t).scene());
            for (raster::SimdLevel level : {raster::SimdLevel::Scalar, raster::SimdLevel::Avx2, raster::SimdLevel::Avx512}) {
                if (!raster::simdLevelSupported(level)) continue;
                INFO(name << " with " << threads << " threads at SIMD level " << int(level));
                FrameSettings settings;
                settings.params = test::quickSettings(t);
                settings.params["caster-lod"] = "0.1";
                settings.simd = level;
                const Frame f = renderFrame(prepared, t, settings);
                if (!first) first = f;
                CHECK(f.shadow.visibility == first->shadow.visibility);
                CHECK(f.radiance == first->radiance);
            }
        }
    }
}
