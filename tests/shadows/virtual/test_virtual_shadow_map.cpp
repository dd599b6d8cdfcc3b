// The `virtual-shadow-map` technique on the sun case: its hard shadow within the shadow
// maps' bounds of the exact reference, every lit pixel covered by a page, the same bytes on
// every thread count and SIMD level; and its cache: kept pages never change an answer (a
// frame with a history gives the same V as one that stands alone), a still frame renders no
// page, a camera move renders only the pages that entered the view, a turn of the sun
// renders them all, and a short pool overflows into counted, lit pixels instead of failing.
#include <doctest/doctest.h>

#include "frame/render.h"
#include "tests/frame/technique_scenes.h"
#include "tests/shadows/shadow_test_support.h"
#include "tests/shadows/virtual/virtual_test_support.h"

using namespace shadowlab;

namespace {

Scene sunScene320() { return test::smallScene(test::sunScene(), 320, 200); }

// The sun case's frames with a history kept from one to the next, and frames alone.
test::KeptFrames sunFrames() { return {sunScene320(), test::smallVirtualMap()}; }

}  // namespace

TEST_CASE("virtual-shadow-map: the sun's hard shadow within the shadow maps' bound, every pixel paged") {
    const test::HardScene s(sunScene320());
    const ShadowOutputs out = s.run("virtual-shadow-map");
    // Sampled, not exact: within 0.05 % of the hit pixels, as close as shadow-map at its
    // default 2048 texels (0.02 % here); a wrong level, page or offset misses by far more.
    const test::Misclassified m = test::misclassified(s.gbuffer, s.reference, s.light(), out.visibility);
    CHECK(m.percent() <= 0.05);
    CHECK(test::misclassified(s.gbuffer, s.reference, s.light(), s.run("shadow-map").visibility).percent() <= 0.05);
    CHECK(test::stat(out, "cache_missing_pixels") == 0);
    CHECK(test::stat(out, "unleveled_pixels") == 0);
    CHECK(test::stat(out, "cache_drawn_pages") == test::stat(out, "requested_pages"));
}

TEST_CASE("virtual-shadow-map: the same bytes on every thread count and SIMD level") {
    const test::HardScene s(sunScene320());
    const std::vector<float> twin = s.run("virtual-shadow-map", test::smallVirtualMap(), raster::SimdLevel::Scalar).visibility;
    test::checkSameBytesEverywhere(twin, [&](raster::SimdLevel level) {
        return s.run("virtual-shadow-map", test::smallVirtualMap(), level).visibility;
    });
}

TEST_CASE("virtual-shadow-map: kept pages never change an answer, and only what is new is rendered") {
    test::KeptFrames s = sunFrames();
    const Frame first = s.next();
    CHECK(test::stat(first.shadow, "cache_drawn_pages") == test::stat(first.shadow, "requested_pages"));
    CHECK(test::stat(first.shadow, "requested_pages") > 4);

    // A still frame: every page is cached.
    const Frame still = s.next();
    CHECK(test::stat(still.shadow, "cache_drawn_pages") == 0);
    CHECK(test::stat(still.shadow, "cache_hit_percent") == 100.0);
    CHECK(test::sameBytes(still.shadow.visibility, first.shadow.visibility));

    // The camera pans: some pages enter the view; the rest are kept and read as drawn.
    Camera camera = s.prepared.scene().camera;
    camera.eye += glm::vec3(1.5f, 0.0f, 0.0f), camera.target += glm::vec3(1.5f, 0.0f, 0.0f);
    s.prepared.setCamera(camera);
    const Frame panned = s.next();
    CHECK(test::stat(panned.shadow, "cache_drawn_pages") > 0);
    CHECK(test::stat(panned.shadow, "cache_drawn_pages") < test::stat(panned.shadow, "requested_pages"));
    CHECK(test::sameBytes(panned.shadow.visibility, s.alone()));

    // The sun turns: every page is drawn again.
    std::vector<Light> lights = s.prepared.scene().lights;
    lights[0].direction = glm::normalize(lights[0].direction + glm::vec3(0.2f, 0.0f, 0.0f));
    s.prepared.setLights(lights);
    const Frame turned = s.next();
    CHECK(test::stat(turned.shadow, "cache_drawn_pages") == test::stat(turned.shadow, "requested_pages"));
    CHECK(test::sameBytes(turned.shadow.visibility, s.alone()));
}

TEST_CASE("virtual-shadow-map: a moving caster re-renders the pages under it, and the kept ones stay right") {
    test::KeptFrames s = sunFrames();
    const Frame first = s.next();
    // The sphere (instance 1) slides 0.4 m along x.
    s.move(1, glm::vec3(0.4f, 0.0f, 0.0f));
    const Frame after = s.next();
    CHECK(test::stat(after.shadow, "cache_invalidated_pages") > 0);
    CHECK(test::stat(after.shadow, "cache_drawn_pages") > 0);
    CHECK(test::stat(after.shadow, "cache_drawn_pages") < test::stat(after.shadow, "requested_pages"));
    CHECK(test::sameBytes(after.shadow.visibility, s.alone()));
    CHECK(!test::sameBytes(after.shadow.visibility, first.shadow.visibility));
}

TEST_CASE("virtual-shadow-map: a pool too small overflows into counted, lit pixels") {
    const test::HardScene s(sunScene320());
    const ShadowOutputs out = s.run("virtual-shadow-map", test::smallVirtualMap({{"pool-pages", "2"}}));
    test::checkOverflowedIntoLitPixels(out);
    // A frame alone hits nothing in the cache: a page without memory is no hit.
    CHECK(test::stat(out, "cache_hit_percent") == 0.0);
}

TEST_CASE("virtual-shadow-map: settings it cannot take are refused by name, and a disk light gets six faces from its centre") {
    const test::HardScene sun(test::hardCase("sun"));
    CHECK_THROWS_WITH_AS(sun.run("virtual-shadow-map", {{"virtual-resolution", "3000"}}),
                         doctest::Contains("resolution must be a power of two"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(sun.run("virtual-shadow-map", {{"first-level", "4"}, {"last-level", "2"}}),
                         doctest::Contains("levels must satisfy"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(sun.run("virtual-shadow-map", {{"page-texels", "8"}}), doctest::Contains("page-texels"),
                         std::invalid_argument);
    // The rays replace the lookup: a filter beside them would go unread.
    CHECK_THROWS_WITH_AS(sun.run("virtual-shadow-map", {{"smrt-rays", "4"}, {"filter", "grid"}}),
                         doctest::Contains("smrt-rays replaces the lookup's filter"), std::invalid_argument);
    CHECK(test::stat(sun.run("virtual-shadow-map"), "virtual_map_flag") == 1.0);
    Scene diskScene = loadScene("sphere-box");
    diskScene.camera.width = 64, diskScene.camera.height = 40;
    const test::HardScene disk(std::move(diskScene));
    const ShadowOutputs local = disk.run("virtual-shadow-map");
    CHECK(test::stat(local, "virtual_map_flag") == 1.0);
    CHECK(test::stat(local, "faces_count") == 6.0);
    CHECK(test::stat(local, "cache_missing_pixels") == 0.0);
}
