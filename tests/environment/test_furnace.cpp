// Furnace tests: a constant environment of radiance L over a Lambert floor of
// albedo a with nothing above it reflects exactly a L; under a ceiling that hides the whole
// sky it reflects nothing. Each technique is held to that with the bound its method allows.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>

#include "tests/environment/environment_scenes.h"
#include "tests/same_bits.h"

using namespace shadowlab;
using namespace shadowlab::test;

namespace {

// The largest relative error of any channel of any hit pixel against a L.
double worstRelativeError(const Frame& f) {
    const glm::vec3 expected = kFloorAlbedo * kFurnaceRadiance;
    double worst = 0.0;
    for (size_t k = 0; k < f.radiance.size(); ++k) {
        if (!f.gbuffer.hit[k]) continue;
        for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(double(f.radiance[k][c]) / expected[c] - 1.0));
    }
    return worst;
}

// The largest channel of any hit pixel, against a L's largest.
double worstRelativeLight(const Frame& f) {
    double worst = 0.0;
    for (size_t k = 0; k < f.radiance.size(); ++k) {
        if (f.gbuffer.hit[k]) worst = std::max(worst, double(glm::max(f.radiance[k].r, glm::max(f.radiance[k].g, f.radiance[k].b))));
    }
    return worst / double(kFloorAlbedo.b * kFurnaceRadiance.b);
}

size_t hits(const Frame& f) { return size_t(std::count(f.gbuffer.hit.begin(), f.gbuffer.hit.end(), uint8_t(1))); }

// The mean over hit pixels of the luminance's error relative to a L's.
double meanRelativeError(const Frame& f) {
    const glm::vec3 e = kFloorAlbedo * kFurnaceRadiance;
    const double expected = 0.2126 * e.r + 0.7152 * e.g + 0.0722 * e.b;
    double sum = 0.0;
    for (size_t k = 0; k < f.radiance.size(); ++k) {
        const glm::vec3& c = f.radiance[k];
        if (f.gbuffer.hit[k]) sum += (0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b) / expected - 1.0;
    }
    return sum / double(hits(f));
}

}  // namespace

TEST_CASE("furnace: an open floor under a constant sky reflects albedo times L") {
    const ScratchDirectory dir("furnace-open");
    const PreparedScene open(furnaceScene(writeConstantMap(dir, kFurnaceRadiance), false));
    // Subtractive: C is SH irradiance, exact for a constant map (E = pi L), and no light is
    // occluded, so S = 0 at every sampling detail: float rounding only.
    for (const char* detail : {"1", "1/16"}) {
        const Frame f = frameOf(open, "env-subtractive", {{"lights", "16"}, {"sampling-detail", detail}});
        REQUIRE(hits(f) > 100);
        CHECK(worstRelativeError(f) < 1e-5);
    }
    // Additive: the lights' powers integrate the map, but a floor sees sum Phi_l max(0, n . d_l),
    // a quadrature of the cosine that converges as N grows (measured 100%, 2.5%, 0.18%).
    const Frame n4 = frameOf(open, "env-additive", {{"lights", "4"}, {"visibility", "exact"}});
    const Frame n64 = frameOf(open, "env-additive", {{"lights", "64"}, {"visibility", "exact"}});
    const Frame n1024 = frameOf(open, "env-additive", {{"lights", "1024"}, {"visibility", "exact"}});
    CHECK(worstRelativeError(n64) < worstRelativeError(n4));
    CHECK(worstRelativeError(n1024) < worstRelativeError(n64));
    CHECK(worstRelativeError(n64) < 0.04);
    CHECK(worstRelativeError(n1024) < 0.004);
    // The exact reference: unbiased, so its image mean is a L within its noise, and its
    // stated convergence (halves_rms_percent, the RMS error it estimates) is of the size it has.
    const Frame reference = frameOf(open, "reference-env", {{"samples", "64"}});
    const double noise = stat(reference, "halves_rms_percent") / 100.0;
    MESSAGE("reference: noise " << noise << ", mean error " << meanRelativeError(reference));
    CHECK(noise > 0.0);
    CHECK(noise < 0.08);
    CHECK(std::abs(meanRelativeError(reference)) < 4.0 * noise / std::sqrt(double(hits(reference))));
}

TEST_CASE("furnace: a floor under a ceiling that hides the whole sky reflects nothing") {
    const ScratchDirectory dir("furnace-ceiling");
    const PreparedScene closed(furnaceScene(writeConstantMap(dir, kFurnaceRadiance), true));
    // Every light is occluded or below the floor: 0 exactly, with every visibility method.
    for (const char* visibility : {"exact", "shadow-map", "shadow-volume"}) {
        INFO(visibility);
        const Frame f = frameOf(closed, "env-additive", {{"lights", "64"}, {"visibility", visibility}});
        REQUIRE(hits(f) > 100);
        CHECK(worstRelativeLight(f) == 0.0);
    }
    // The planes are 1000 m wide: rays within atan(1 / 500) of the horizon pass their edge
    // and see the sky, a share of the cosine-weighted hemisphere under 1e-5; the
    // reference's rare hits there stay under 1e-3 of a L at any pixel.
    const Frame reference = frameOf(closed, "reference-env", {{"samples", "16"}});
    CHECK(worstRelativeLight(reference) < 1e-3);
    // Subtractive: S, the sum of the occluded lights, is C up to the lights' quadrature
    // error; where it exceeds C the difference is clamped to 0 (and counted).
    for (const char* lights : {"16", "256"}) {
        const Frame f = frameOf(closed, "env-subtractive", {{"lights", lights}, {"visibility", "exact"}});
        CHECK(worstRelativeLight(f) < 0.05);
        // The lights' quadrature overshoots C in some channel at every pixel here: all clamped.
        CHECK(stat(f, "clamped_pixels") == double(hits(f)));
    }
}

// The exact visibility of the environment techniques (reference-env's rays, and the
// lights' with visibility=exact) is the reference's, through a cut-out's holes: a ceiling
// whose texture is all holes hides nothing, the same ceiling all solid hides the sky as the
// plain one does, byte for byte. Built without the casters' transmission, the rays took
// every card as solid.
TEST_CASE("furnace: the exact environment visibility sees through a cut-out ceiling's holes") {
    const ScratchDirectory dir("furnace-cut-out");
    const std::string map = writeConstantMap(dir, kFurnaceRadiance);
    const auto cutOutCeiling = [&](float alpha) {
        Scene scene = furnaceScene(map, true);
        scene.alphaTextures.push_back({.source = "test", .width = 2, .height = 2, .alpha = std::vector<float>(4, alpha), .wrap = {}});
        scene.materials.push_back({.name = "ceiling", .albedo = kFloorAlbedo, .alphaTexture = 0, .alphaCutoff = 0.5f});
        scene.instances[1].material = 1;
        return PreparedScene(scene);
    };
    const PreparedScene open(furnaceScene(map, false)), closed(furnaceScene(map, true));
    const PreparedScene holes = cutOutCeiling(0.0f), solid = cutOutCeiling(1.0f);
    const std::pair<const char*, std::map<std::string, std::string>> runs[] = {
        {"reference-env", {{"samples", "8"}}}, {"env-additive", {{"lights", "16"}, {"visibility", "exact"}}}};
    for (const auto& run : runs) {   // not a structured binding: clang 14 cannot capture one in INFO
        const char* technique = run.first;
        const std::map<std::string, std::string>& params = run.second;
        INFO(technique);
        CHECK(sameBytes(frameOf(holes, technique, params).radiance, frameOf(open, technique, params).radiance));
        CHECK(sameBytes(frameOf(solid, technique, params).radiance, frameOf(closed, technique, params).radiance));
    }
}

// The floor's albedo from an albedo texture (shading/surface_albedo.h): a white material
// whose one texel is kFloorAlbedo reflects kFloorAlbedo L, as the plain floor does; a
// stage that read the material's albedo alone would reflect L. The radiance cache, one
// albedo per material, refuses it by name.
TEST_CASE("furnace: a floor whose albedo is its texture's reflects the texel's albedo times L") {
    const ScratchDirectory dir("furnace-textured");
    Scene scene = furnaceScene(writeConstantMap(dir, kFurnaceRadiance), false);
    scene.materials[0].albedo = glm::vec3(1.0f);
    scene.materials[0].albedoTexture = 0;
    scene.albedoTextures.push_back({.source = "one texel", .width = 1, .height = 1, .albedo = {kFloorAlbedo}});
    const PreparedScene textured(std::move(scene));
    const Frame subtractive = frameOf(textured, "env-subtractive", {{"lights", "16"}});
    REQUIRE(hits(subtractive) > 100);
    CHECK(worstRelativeError(subtractive) < 1e-5);
    const Frame additive = frameOf(textured, "env-additive", {{"lights", "64"}, {"visibility", "exact"}});
    CHECK(worstRelativeError(additive) < 0.04);
    const Frame reference = frameOf(textured, "reference-env", {{"samples", "16"}});
    const double noise = stat(reference, "halves_rms_percent") / 100.0;
    CHECK(std::abs(meanRelativeError(reference)) < 4.0 * noise / std::sqrt(double(hits(reference))));
    CHECK_THROWS_WITH_AS(frameOf(textured, "env-subtractive", {{"unshadowed", "radiance-cache"}}),
                         "material \"floor\": the radiance cache holds one albedo per material, and this one has an "
                         "albedo texture; use --param unshadowed=tables",
                         std::invalid_argument);
}
