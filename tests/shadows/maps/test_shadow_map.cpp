// `shadow-map` against the exact reference: acne and leaks at the default settings, cube
// faces around a point light, every bias mode, determinism across threads, bad params.
#include <doctest/doctest.h>


#include "raster/thread_count.h"
#include "tests/shadows/maps/shadow_map_test_util.h"
#include "tests/same_bits.h"

using namespace shadowlab;
using namespace shadowlab::test;

TEST_CASE("shadow-map, defaults, sphere-box: acne below 0.05% of lit pixels, leaks only at the boundary") {
    const Scene scene = loadScene("sphere-box");   // full 1280x800: the bound is for the full view
    const PreparedScene prepared(scene);
    const Frame reference = frameOf(prepared, "reference");
    const Frame map = frameOf(prepared, "shadow-map");
    // The band comes from the density measured here; the technique's own figure must agree.
    const double density = measuredTexelsPerPixel(map, prepared, 2048);
    CHECK(statOf(map, "resolution_texels") == 2048);
    CHECK(density > 0.5);
    CHECK(statOf(map, "median_texels_per_pixel") == doctest::Approx(density).epsilon(0.05));   // 2.348 and 2.379
    const BandedErrors m = bandedErrors(reference, map, leakBandPixels(density));
    MESSAGE("acne " << m.falseShadow << " of " << m.lit << " lit, leaks " << m.falseLight << " of " << m.shadowed
                    << " shadowed, texels/pixel " << density);
    CHECK(m.falseShadow < 0.0005 * m.lit);
    CHECK(m.falseLightOffBoundary == 0);
    CHECK(m.falseShadowOffBoundary <= m.falseShadow);
    // Leaks only along the outline: fewer than 1% of the shadowed pixels.
    CHECK(m.falseLight < 0.01 * m.shadowed);
}

TEST_CASE("shadow-map: every bias mode and depth layer keeps errors at the shadow boundary") {
    Scene scene = loadScene("sphere-box");
    scene.camera.width = 640, scene.camera.height = 400;
    const PreparedScene prepared(scene);
    const Frame reference = frameOf(prepared, "reference");
    const std::vector<std::map<std::string, std::string>> variants = {
        {{"bias", "constant"}},         {{"bias", "receiver-plane"}}, {{"bias", "normal-offset"}},
        {{"layer", "second"}, {"bias", "constant"}, {"constant-bias", "0"}}, {{"layer", "midpoint"}},
        {{"filter", "bilinear"}},       {{"filter", "grid"}},         {{"filter", "poisson"}},
    };
    const double density = measuredTexelsPerPixel(reference, prepared, 2048);
    for (const auto& params : variants) {
        const Frame map = frameOf(prepared, "shadow-map", params);
        const BandedErrors m = bandedErrors(reference, map, leakBandPixels(density));
        INFO(params.begin()->first << "=" << params.begin()->second << ": acne " << m.falseShadow << " of " << m.lit
                                   << ", leaks " << m.falseLight << " of " << m.shadowed);
        CHECK(m.falseShadow < 0.005 * m.lit);
        CHECK(m.falseLight < 0.03 * m.shadowed);
    }
}

TEST_CASE("shadow-map: six cube faces around a point light leave no gap") {
    Scene scene = loadScene("sphere-box");
    scene.camera.width = 480, scene.camera.height = 300;
    scene.lights[0].type = LightType::Point;
    scene.lights[0].position = glm::vec3(0.0f, 0.5f, 2.0f);   // low, in front of the sphere: receivers all around
    const PreparedScene prepared(scene);
    const Frame reference = frameOf(prepared, "reference");
    const Frame map = frameOf(prepared, "shadow-map", {{"resolution", "1024"}});
    CHECK(statOf(map, "maps_count") >= 4);
    const BandedErrors m = bandedErrors(reference, map, leakBandPixels(statOf(map, "median_texels_per_pixel")));
    MESSAGE("cube: acne " << m.falseShadow << ", leaks " << m.falseLight << " of " << m.lit + m.shadowed);
    CHECK(m.falseLightOffBoundary == 0);
    CHECK(m.falseShadow < 0.001 * m.lit);
    // Forcing the cube on the ordinary (far) light gives the same answer as one frustum.
    Scene far = loadScene("sphere-box");
    far.camera.width = 480, far.camera.height = 300;
    far.lights[0].type = LightType::Point;
    const PreparedScene farPrepared(far);
    const Frame farReference = frameOf(farPrepared, "reference");
    const Frame forced = frameOf(farPrepared, "shadow-map", {{"cube", "always"}, {"resolution", "1024"}});
    const BandedErrors f = bandedErrors(farReference, forced, leakBandPixels(statOf(forced, "median_texels_per_pixel")));
    CHECK(f.falseLightOffBoundary == 0);
    CHECK(f.falseShadow < 0.001 * f.lit);
}

TEST_CASE("shadow-map and csm: the same V bytes with 1 and 2 threads") {
    const Scene scene = sunSphereBox(320, 200);
    const PreparedScene prepared(scene);
    const std::vector<std::pair<std::string, std::map<std::string, std::string>>> runs = {
        {"shadow-map", {{"filter", "poisson"}, {"resolution", "512"}}},
        {"shadow-map", {{"warp", "lispsm"}, {"filter", "bilinear"}, {"resolution", "512"}}},
        {"csm", {{"filter", "grid"}, {"resolution", "512"}}},
    };
    for (const auto& run : runs) {
        const std::string& technique = run.first;
        const std::map<std::string, std::string>& params = run.second;
        std::vector<float> v[2];
        for (int threads : {1, 2}) {
            v[threads - 1] = withThreads(threads, [&] { return frameOf(prepared, technique, params).shadow.visibility; });
        }
        INFO(technique);
        REQUIRE(v[0].size() == v[1].size());
        CHECK(test::sameBytes(v[0], v[1]));
    }
}

TEST_CASE("shadow-map and csm: bad parameters are errors that name them") {
    const Scene point = [] {
        Scene s = loadScene("sphere-box");
        s.camera.width = 64, s.camera.height = 40;
        return s;
    }();
    const auto fails = [&](const Scene& scene, const std::string& technique, const std::map<std::string, std::string>& p,
                           const std::string& needle) {
        try {
            frameOf(PreparedScene(scene), technique, p);
        } catch (const std::invalid_argument& e) {
            return std::string(e.what()).find(needle) != std::string::npos;
        }
        return false;
    };
    CHECK(fails(point, "shadow-map", {{"resolution", "8"}}, "resolution"));
    CHECK(fails(point, "shadow-map", {{"filter", "gaussian"}}, "filter"));
    CHECK(fails(point, "shadow-map", {{"bias", "none"}}, "bias"));
    CHECK(fails(point, "shadow-map", {{"grid-size", "1"}}, "grid-size"));
    CHECK(fails(point, "shadow-map", {{"sharpness", "1"}}, "sharpness"));
    CHECK(fails(point, "shadow-map", {{"warp", "lispsm"}}, "directional"));
    CHECK(fails(point, "csm", {{"cascades", "9"}}, "cascades"));   // read, though a local light takes no cascades
    CHECK(fails(sunSphereBox(64, 40), "csm", {{"cascades", "9"}}, "cascades"));
    CHECK(fails(sunSphereBox(64, 40), "csm", {{"split", "cubic"}}, "split"));
    CHECK(fails(sunSphereBox(64, 40), "shadow-map", {{"cube", "always"}}, "point light"));
}
