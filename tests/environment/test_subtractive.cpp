// Subtractive shadows against their baseline and the exact reference: the claims of
// DeCoro and Rusinkiewicz 2008 that should hold, on the glossy bunny (assets/scenes/environment/
// bunny-interior.json) and the glossy sphere under a sky (sphere-sky.json) at small sizes:
// subtractive beats additive at equal N on a glossy model; the additive image converges to
// the exact one as N grows; C matches the exact light where nothing is occluded; S' = S at
// sampling detail 1; lower sampling detail shades fewer fragments (counted, not timed); the
// radiance cache lights Blinn-Phong; the same bytes for any thread count and SIMD level;
// bad input refused.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include <tbb/global_control.h>

#include "frame/registry.h"
#include "frame/score.h"
#include "shadows/environment/bilateral_upsample.h"
#include "tests/environment/environment_scenes.h"
#include "tests/same_bits.h"

using namespace shadowlab;
using test::sameBytes;
using namespace shadowlab::test;

namespace {

// The paper's glossy bunny (Phong 40) under the interior map, its exact reference (1024
// samples per strategy), and the RMS of a frame's luminance against it. The claim is the
// paper's, on its kind of scene: under a map with a sun (sphere-sky) the nine-term SH
// irradiance is 8% off on average (docs/environment-lighting.md) and C's error outweighs
// what subtraction gains, which docs/subtractive-shadows.md shows.
struct BunnyCase {
    PreparedScene prepared{[] {
        Scene scene = loadScene(std::string(SHADOWLAB_SOURCE_DIR) + "/assets/scenes/environment/bunny-interior.json");
        scene.camera.width = 96, scene.camera.height = 60;
        return scene;
    }()};
    Frame exact = frameOf(prepared, "reference-env", {{"samples", "1024"}});
    double rms(const Frame& f) const { return scoreFrame(scoredImage(exact), f).rms; }
};

}  // namespace

TEST_CASE("subtractive shadows: lower RMS than additive at equal N on the glossy bunny, and additive converges as N grows") {
    const BunnyCase sky;
    MESSAGE("reference noise (RMS of Y) " << stat(sky.exact, "halves_rms_radiance"));
    for (const char* lights : {"20", "40"}) {
        const double additive = sky.rms(frameOf(sky.prepared, "env-additive", {{"lights", lights}}));
        const double subtractive = sky.rms(frameOf(sky.prepared, "env-subtractive", {{"lights", lights}}));
        MESSAGE(std::string(lights) << " lights: additive " << additive << ", subtractive " << subtractive);
        CHECK(subtractive < additive);
    }
    double previous = 1e30;
    for (const char* lights : {"4", "32", "256"}) {
        const double rms = sky.rms(frameOf(sky.prepared, "env-additive", {{"lights", lights}, {"visibility", "exact"}}));
        MESSAGE("additive, exact visibility, " << std::string(lights) << " lights: " << rms);
        CHECK(rms < previous);
        previous = rms;
    }
}

TEST_CASE("subtractive shadows: C, the unshadowed light, matches the exact reference on a sphere that shadows nothing") {
    // A lone convex sphere (Phong 40, the paper's bunny material) under the interior map:
    // nothing is occluded, so env-subtractive's image is C (S = 0), and its error against
    // the exact integral is fast local illumination's own: per direction the nine-term SH
    // diffuse is 0-9% off and the prefiltered Phong lobe 0-8% (brute force over the map's
    // texels), heaviest in the window's bright reflection, so the image's RMS is 15% of its
    // mean luminance (reference noise 2.3%). A C without its specular term, or with SH
    // irradiance not divided by pi, is off by 30% or more.
    Scene scene = skyScene(64, 64);
    scene.meshes = {makeUvSphere(1.0f, 96, 48)};
    scene.materials = {{.name = "glossy", .model = MaterialModel::Phong, .albedo = glm::vec3(0.35f, 0.3f, 0.25f),
                        .specular = glm::vec3(0.4f), .shininess = 40.0f}};
    scene.instances = {{.name = "sphere", .mesh = 0, .material = 0}};
    scene.camera.eye = {0.0f, 0.5f, 3.2f}, scene.camera.target = {0.0f, 0.0f, 0.0f}, scene.camera.fovyDeg = 45.0f;
    scene.environment.map = std::string(SHADOWLAB_SOURCE_DIR) + "/assets/environments/blender_interior.exr";
    const PreparedScene sphere(scene);
    const Frame exact = frameOf(sphere, "reference-env", {{"samples", "1024"}});
    const Frame C = frameOf(sphere, "env-subtractive", {{"lights", "40"}});
    const double meanY = meanLuminance(exact);
    const double rms = scoreFrame(scoredImage(exact), C).rms, noise = stat(exact, "halves_rms_radiance");
    MESSAGE("C against the exact reference: RMS " << rms / meanY * 100.0 << "% of the mean, reference noise "
                                                  << noise / meanY * 100.0 << "%");
    CHECK(rms < 0.2 * meanY);
}

TEST_CASE("subtractive shadows: S' = S at sampling detail 1, and a constant S resamples to itself") {
    const PreparedScene sky(skyScene(64, 40));
    const Frame f = frameOf(sky, "env-subtractive", {{"lights", "8"}});
    const std::vector<glm::vec3> S(f.gbuffer.pixelCount(), glm::vec3(0.25f, 0.5f, 1.0f));
    CHECK(sameBytes(upsampleShadowBuffer(f.gbuffer, sky.scene().camera, f.gbuffer, S), S));

    const Camera small = [&] { Camera c = sky.scene().camera; c.width = 16, c.height = 10; return c; }();
    const GBuffer sampled = renderGBuffer(sky.world(), small, raster::bestSimdLevel());
    const std::vector<glm::vec3> constant(sampled.pixelCount(), glm::vec3(0.25f, 0.5f, 1.0f));
    UpsampleCounts counts;
    const std::vector<glm::vec3> resampled = upsampleShadowBuffer(f.gbuffer, sky.scene().camera, sampled, constant, &counts);
    for (size_t k = 0; k < resampled.size(); ++k) {
        if (!f.gbuffer.hit[k] || resampled[k] == glm::vec3(0.0f)) continue;   // 0: no hit sample near
        CHECK(glm::all(glm::lessThan(glm::abs(resampled[k] - constant[0]), glm::vec3(1e-6f))));
    }
    CHECK(counts.emptyPixels < f.gbuffer.pixelCount() / 50);

    // S = the sampled points' world x: S' should be p's own x, to within the kernel's reach.
    // Measured in units of one sampled pixel's footprint at p: a window off by one sampled
    // pixel biases the mean by about one.
    std::vector<glm::vec3> ramp(sampled.pixelCount(), glm::vec3(0.0f));
    for (size_t q = 0; q < ramp.size(); ++q) ramp[q] = glm::vec3(sampled.position[q].x);
    const std::vector<glm::vec3> rampResampled = upsampleShadowBuffer(f.gbuffer, sky.scene().camera, sampled, ramp);
    const Camera& c = sky.scene().camera;
    double signedSum = 0.0, absSum = 0.0;
    size_t n = 0;
    for (int j = 0; j < c.height; ++j) {
        for (int i = 0; i < c.width; ++i) {
            const size_t k = f.gbuffer.index(i, j);
            if (!f.gbuffer.hit[k] || i < 8 || j < 8 || i >= c.width - 8 || j >= c.height - 8) continue;   // borders clamp
            const double footprint = 4.0 * 2.0 * std::tan(c.fovyDeg * 3.141592653589793 / 360.0) / c.height *
                                     glm::length(f.gbuffer.position[k] - c.eye);
            const double error = (rampResampled[k].x - f.gbuffer.position[k].x) / footprint;
            signedSum += error, absSum += std::abs(error), ++n;
        }
    }
    MESSAGE("ramp: mean error " << signedSum / n << ", mean |error| " << absSum / n << " sampled-pixel footprints");
    CHECK(std::abs(signedSum / n) < 0.25);
    CHECK(absSum / n < 0.5);
}

TEST_CASE("subtractive shadows: each lower sampling detail shades fewer shadow fragments") {
    const PreparedScene sky(skyScene(128, 80));
    double previous = 1e30;
    for (const char* detail : {"1", "1/4", "1/16", "1/64"}) {
        const double fragments = stat(frameOf(sky, "env-subtractive", {{"lights", "16"}, {"sampling-detail", detail}}),
                                      "shadow_fragments");
        MESSAGE(std::string(detail) << ": " << fragments);
        CHECK(fragments > 0.0);
        CHECK(fragments < previous);
        previous = fragments;
    }
}

TEST_CASE("environment techniques: the same bytes for 1 and 2 threads and every SIMD level") {
    const PreparedScene sky(skyScene(64, 40));
    const std::vector<std::pair<std::string, std::map<std::string, std::string>>> cases = {
        {"env-subtractive", {{"lights", "8"}, {"sampling-detail", "1/16"}}},
        {"env-subtractive", {{"lights", "8"}, {"visibility", "shadow-volume"}}},
        {"env-additive", {{"lights", "8"}}},
        {"reference-env", {{"samples", "8"}}}};
    for (const auto& c : cases) {   // not a structured binding: clang 14 cannot capture one in INFO
        INFO(c.first);
        std::vector<glm::vec3> first;
        for (int threads : {1, 2}) {
            const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
            for (raster::SimdLevel level : {raster::SimdLevel::Scalar, raster::SimdLevel::Avx2, raster::SimdLevel::Avx512}) {
                if (!raster::simdLevelSupported(level)) continue;
                FrameSettings settings;
                settings.params = c.second;
                settings.simd = level;
                const Frame f = renderFrame(sky, findTechnique(c.first), settings);
                if (first.empty()) first = f.radiance;
                CHECK(sameBytes(f.radiance, first));
            }
        }
    }
}

TEST_CASE("environment techniques: refused without an environment map, and with an odd reference sample count") {
    Scene noMap = skyScene(32, 20);
    noMap.environment.map.clear();
    noMap.lights.push_back({});
    const PreparedScene plain(noMap);
    for (const char* t : {"env-additive", "env-subtractive", "reference-env", "reference-env-lights"}) {
        CHECK_THROWS_WITH_AS(frameOf(plain, t), "the scene names no environment map (environment.map in the scene file)",
                             std::invalid_argument);
    }
    const PreparedScene sky(skyScene(32, 20));
    CHECK_THROWS_WITH_AS(frameOf(sky, "reference-env", {{"samples", "3"}}), "reference-env: samples must be even (two halves)",
                         std::invalid_argument);
}

TEST_CASE("subtractive shadows: a Blinn-Phong material is refused by the tables, named, and lit by the radiance cache") {
    Scene scene = skyScene(64, 40);
    scene.materials[1].model = MaterialModel::BlinnPhong;   // the sphere
    scene.materials[1].shininess = 60.0f;
    const PreparedScene blinn(scene);
    CHECK_THROWS_WITH_AS(frameOf(blinn, "env-subtractive"),
                         "material \"sphere\": prefiltered tables cannot light it (Blinn-Phong, or a lobe too sharp for "
                         "the map); use --param unshadowed=radiance-cache",
                         std::invalid_argument);
    const Frame cached = frameOf(blinn, "env-subtractive", {{"unshadowed", "radiance-cache"}, {"cache-size", "64"}});
    const Frame exact = frameOf(blinn, "reference-env", {{"samples", "256"}});
    const double meanY = meanLuminance(exact);
    const double rms = scoreFrame(scoredImage(exact), cached).rms;
    MESSAGE("Blinn-Phong sphere under the sky: radiance cache RMS " << 100.0 * rms / meanY << "% of the mean, reference noise "
                                                                   << 100.0 * stat(exact, "halves_rms_radiance") / meanY << "%");
    CHECK(stat(cached, "radiance_caches_count") == 3.0);
    CHECK(rms < 0.1 * meanY);   // measured 5.2%: the distant viewer and the SH-free integral's own error
}

TEST_CASE("subtractive shadows: the radiance cache's C agrees with the tables' where both serve (a Phong sphere)") {
    const PreparedScene sky(skyScene(64, 40));
    const Frame tables = frameOf(sky, "env-subtractive", {{"lights", "8"}});
    const Frame cached = frameOf(sky, "env-subtractive", {{"lights", "8"}, {"unshadowed", "radiance-cache"}});
    double difference = 0.0, total = 0.0;
    for (size_t k = 0; k < tables.radiance.size(); ++k) {
        if (!tables.gbuffer.hit[k]) continue;
        difference += glm::length(glm::dvec3(tables.radiance[k] - cached.radiance[k]));
        total += glm::length(glm::dvec3(tables.radiance[k]));
    }
    MESSAGE("mean |C_tables - C_cache| / mean |C_tables| = " << difference / total);
    CHECK(difference / total < 0.06);   // measured 2.9%: each is an approximation of the same integral
}

TEST_CASE("subtractive shadows: a sampled image of one pixel (1/1024 of a small view) gives a finite image") {
    // One receiver: the lights' views fit a point, which light-view fitting widens to a
    // finite size rather than an infinite projection.
    const PreparedScene sky(skyScene(32, 20));
    for (const char* visibility : {"shadow-map", "shadow-volume", "exact"}) {
        INFO(visibility);
        const Frame f = frameOf(sky, "env-subtractive", {{"lights", "8"}, {"sampling-detail", "1/1024"}, {"visibility", visibility}});
        CHECK(stat(f, "sampled_pixels") <= 1.0);
        for (const glm::vec3& c : f.radiance) CHECK((std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b)));
    }
}

TEST_CASE("environment techniques: the scene preparation builds what the settings read, once") {
    const auto names = [](const Frame& f) {
        std::vector<std::string> built;
        for (const TechniqueStat& s : f.preparation) built.push_back(s.name);
        return built;
    };
    const PreparedScene cached(skyScene(32, 20));
    CHECK(names(frameOf(cached, "env-subtractive", {{"lights", "4"}, {"unshadowed", "radiance-cache"}})) ==
          std::vector<std::string>{"environment_ms"});
    CHECK(names(frameOf(cached, "env-subtractive", {{"lights", "4"}, {"visibility", "shadow-volume"}})) ==
          std::vector<std::string>{"edge_adjacency_ms", "local_illumination_ms"});
    CHECK(names(frameOf(cached, "env-subtractive", {{"lights", "4"}})).empty());   // all built already
}
