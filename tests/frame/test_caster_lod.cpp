// Caster level of detail in the frame (frame/render.h, scenes/caster_lod.h): every technique
// but the references takes `caster-lod`, draws the simplified casters and still sees the
// whole receivers; the simplification is scene preparation; at ratio 1 nothing changes.
#include <doctest/doctest.h>

#include <algorithm>
#include <string>

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
            ++litOnSphere;
            stillLit += scored(coarse)[k] == 1.0f;
        }
        REQUIRE(litOnSphere > 1000);
        CHECK(stillLit == litOnSphere);
    }
}

TEST_CASE("caster LOD: the bunny's shadow error grows as its triangles drop, and stays within bounds") {
    Scene scene = test::smallScene("bunny", 320, 200);
    const PreparedScene prepared(std::move(scene));
    const ImageChannels reference = renderReferenceImage(prepared, raster::bestSimdLevel(), "reference");
    const Technique& t = findTechnique("shadow-volume");
    double previous = -1.0;
    for (const char* lod : {"1", "0.1", "0.01"}) {
        INFO(lod);
        const Frame frame = frameAt(prepared, t, lod, false);
        const ErrorFigures e = scoreFrame(reference, frame);
        const double misclassified = 100.0 * double(e.misclassified()) / double(e.pixels);
        CHECK(misclassified >= previous);
        CHECK(misclassified < 0.5);   // % of hit pixels: the outline moves, the shadow stays
        previous = misclassified;
    }
    CHECK(previous > 0.02);   // at 1% of the triangles the outline has moved visibly
}
