// shadow-volume (shadows/volumes/shadow_volume.cpp): the exact techniques' bound on the
// built-in scenes (test::kExactBoundPercent: at most 0.01% of pixels misclassified against
// the exact reference, each within one pixel of a reference shadow boundary), z-pass
// against z-fail, and the same bytes for 1 and 2 threads and every SIMD level.
#include <doctest/doctest.h>

#include "raster/thread_count.h"
#include "shading/lights.h"
#include "shadows/silhouettes/silhouette.h"
#include "shadows/volumes/counting_mode.h"
#include "tests/shadows/shadow_test_support.h"

using namespace shadowlab;

TEST_CASE("shadow-volume: built-in scenes within 0.01% of the reference, errors only next to shadow boundaries") {
    for (const char* name : {"sphere-box", "bunny"}) {
        const test::HardScene s(name);
        test::requireBound(s, s.run("shadow-volume"), name);
    }
}

TEST_CASE("shadow-volume: throughput (4.1 M triangles) within 0.01% of the reference") {
    const test::HardScene s("throughput");
    test::requireBound(s, s.run("shadow-volume"), "throughput");
}

TEST_CASE("shadow-volume: z-pass and z-fail give the same stencil when the camera is outside every volume") {
    for (const char* name : {"sphere-box", "bunny"}) {
        const test::HardScene s(name);
        const Camera& c = s.scene.camera;
        CHECK_FALSE(nearPlaneMayBeShadowed(c, homogeneousLight(s.scene.lights[0]), instanceBounds(s.scene, s.world)));
        const ShadowOutputs pass = s.run("shadow-volume", {{"mode", "zpass"}});
        const ShadowOutputs fail = s.run("shadow-volume", {{"mode", "zfail"}});
        CHECK(test::stat(s.run("shadow-volume"), "zfail_flag") == 0.0);
        CHECK(pass.visibility == fail.visibility);
        size_t differentCounts = 0;
        for (size_t k = 0; k < pass.stencil.size(); ++k) differentCounts += s.gbuffer.hit[k] && pass.stencil[k] != fail.stencil[k];
        CHECK(differentCounts == 0);
        // z-fail draws the caps too: more fill for the same answer.
        CHECK(test::stat(fail, "fill_fragments") > test::stat(pass, "fill_fragments"));
    }
}

TEST_CASE("shadow-volume: the same bytes for 1 and 2 threads and every SIMD level") {
    const test::HardScene s("sphere-box");
    const auto runWith = [&](int threads, raster::SimdLevel simd) {
        return withThreads(threads, [&] { return s.run("shadow-volume", {{"mode", "zfail"}}, simd); });
    };
    const ShadowOutputs one = runWith(1, raster::bestSimdLevel());
    for (const raster::SimdLevel simd : {raster::SimdLevel::Scalar, raster::bestSimdLevel()}) {
        const ShadowOutputs two = runWith(2, simd);
        CHECK(one.visibility == two.visibility);
        CHECK(one.stencil == two.stencil);
        CHECK(test::stat(one, "fill_fragments") == test::stat(two, "fill_fragments"));
    }
}
