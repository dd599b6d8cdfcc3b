// planar (shadows/planar/planar.cpp): the projection matrix of RTR 7.1.1, the ground shadow against
// the exact reference, the stencil against double blending, and the technique's known
// failure modes, asserted as such: no self-shadowing (the sphere's own terminator is
// missed), no shadows on anything but the receiver plane (a box under a slab stays lit).
#include <doctest/doctest.h>

#include <filesystem>

#include "frame/registry.h"
#include "raster/thread_count.h"
#include "shading/image_io.h"
#include "shadows/planar/planar.h"
#include "tests/shadows/shadow_test_support.h"

using namespace shadowlab;

namespace {

// Misclassified pixels on the ground plane, % of its pixels, on any hard case (measured
// 2026-11-22: see the test at the end).
constexpr double kGroundBoundPercent = 0.05;

// Hit pixels split by whether their surface belongs to instance `receiver`.
struct Split {
    test::Misclassified onReceiver, elsewhere;
    size_t elsewhereShadowed = 0;   // V = 0 in the test off the receiver
};

Split splitErrors(const test::HardScene& s, const std::vector<float>& v, uint32_t receiver) {
    Split split;
    const GBuffer& g = s.gbuffer;
    for (int j = 0; j < g.height; ++j) {
        for (int i = 0; i < g.width; ++i) {
            const size_t k = g.index(i, j);
            if (!g.hit[k]) continue;
            const bool onReceiver = s.world.triangleInstance[g.triangle[k]] == receiver;
            test::Misclassified& m = onReceiver ? split.onReceiver : split.elsewhere;
            split.elsewhereShadowed += !onReceiver && v[k] == 0.0f;
            m.hitPixels++;
            if (s.reference[k] == v[k]) continue;
            m.count++;
            (s.reference[k] == 1.0f ? m.falseShadow : m.falseLight)++;
            m.awayFromBoundary += !test::nearReferenceBoundary(g, s.reference, s.light(), i, j);
        }
    }
    return split;
}

}  // namespace

TEST_CASE("planar: the projection matrix sends points along the light's rays onto the plane") {
    const glm::dvec4 plane(0.0, 1.0, 0.0, -0.25);   // y = 0.25
    for (const glm::dvec4 light : {glm::dvec4(4, 8, 3, 1), glm::dvec4(0.4, 0.8, 0.3, 0)}) {
        const glm::dmat4 M = planarProjection(plane, light);
        for (const glm::dvec3 p : {glm::dvec3(0, 1.2, 0), glm::dvec3(2, 1.5, -1), glm::dvec3(-3, 0.25, 7)}) {
            const glm::dvec4 h = M * glm::dvec4(p, 1.0);
            const glm::dvec3 q = glm::dvec3(h) / h.w;
            CHECK(q.y == doctest::Approx(0.25));
            // q - p is parallel to the direction towards the light.
            const glm::dvec3 towards = glm::dvec3(light) - light.w * p;
            CHECK(glm::length(glm::cross(q - p, towards)) == doctest::Approx(0.0).epsilon(1e-9).scale(1.0));
        }
    }
}

TEST_CASE("planar: sphere-box's ground shadow matches the reference, the objects' own shadows are its failure mode") {
    const test::HardScene s("sphere-box");
    const ShadowOutputs out = s.run("planar");
    const Split split = splitErrors(s, out.visibility, 0);   // instance 0: the ground
    INFO("ground: " << split.onReceiver.count << " of " << split.onReceiver.hitPixels << " misclassified, "
                    << split.onReceiver.awayFromBoundary << " away from a boundary; elsewhere " << split.elsewhere.count);
    CHECK(split.onReceiver.percent() <= 0.01);
    CHECK(split.onReceiver.awayFromBoundary == 0);
    // Known failure mode (RTR 7.1.1; Lehtinen 2015, "Limitations of Planar Shadows"): no
    // self-shadows, no shadows on other objects. The sphere's unlit half and the box's
    // faces turned from the light keep V = 1, all of it false light, none false shadow.
    CHECK(split.elsewhereShadowed == 0);
    CHECK(split.elsewhere.falseShadow == 0);
    CHECK(split.elsewhere.falseLight > 5000);
    CHECK(test::stat(out, "receiver_triangles") == 8192.0);
}

TEST_CASE("planar: the sphere's own terminator is missed") {
    const test::HardScene s(test::hardCase("sphere-terminator"));
    const ShadowOutputs out = s.run("planar");
    const GBuffer& g = s.gbuffer;
    size_t unlitSide = 0, unlitSideLit = 0;
    for (size_t k = 0; k < g.pixelCount(); ++k) {
        if (!g.hit[k] || s.world.triangleInstance[g.triangle[k]] != 1 || test::facesLight(g, k, s.light())) continue;
        unlitSide++;
        unlitSideLit += out.visibility[k] == 1.0f;
    }
    CHECK(unlitSide > 10000);
    CHECK(unlitSideLit == unlitSide);
}

TEST_CASE("planar: only the plane receives: a box under a slab stays lit, a plane off the ground casts nothing") {
    const test::HardScene s(test::hardCase("camera-in-shadow"));
    const std::vector<float> v = s.run("planar").visibility;
    const Split onGround = splitErrors(s, v, 0);
    CHECK(onGround.onReceiver.percent() <= 0.01);
    CHECK(onGround.onReceiver.awayFromBoundary == 0);
    // The box (instance 2) stands under the slab, in its shadow in the reference.
    size_t boxPixels = 0, boxShadowedInReference = 0, boxShadowedHere = 0;
    for (size_t k = 0; k < s.gbuffer.pixelCount(); ++k) {
        if (!s.gbuffer.hit[k] || s.world.triangleInstance[s.gbuffer.triangle[k]] != 2) continue;
        boxPixels++;
        boxShadowedInReference += s.reference[k] == 0.0f;
        boxShadowedHere += v[k] == 0.0f;
    }
    CHECK(boxPixels > 1000);
    CHECK(boxShadowedInReference == boxPixels);
    CHECK(boxShadowedHere == 0);
    // With the receiver plane at y = 1 no instance lies in it: no receiver, no shadow.
    const ShadowOutputs raised = s.run("planar", {{"plane-y", "1"}});
    CHECK(test::stat(raised, "receiver_pixels") == 0.0);
    CHECK(test::stat(raised, "shadowed_receiver_pixels") == 0.0);
}

TEST_CASE("planar: the stencil blends each shadowed pixel once, the same bytes for 1 and 2 threads") {
    const test::HardScene s("sphere-box");
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "shadowlab-test-planar";
    const Technique& planar = findTechnique("planar");
    const TechniqueParams params(planar.name, planar.params, {{"opacity", "0.5"}});
    const auto runWith = [&](int threads, const std::filesystem::path& debugDir) {
        return withThreads(threads, [&] {
            return planar.run({.prepared = s.prepared,
                               .gbuffer = s.gbuffer,
                               .light = s.scene.lights[0],
                               .simd = raster::bestSimdLevel(),
                               .params = params,
                               .debugDir = debugDir});
        });
    };
    const ShadowOutputs one = runWith(1, dir), two = runWith(2, {});
    CHECK(one.visibility == two.visibility);
    CHECK(one.stencil == two.stencil);
    // The sphere's projected triangles overlap each other many times over; with the
    // stencil test "equal 0, increment" each shadowed pixel is darkened exactly once:
    // white blended once with (0, 0, 0, 0.5) is 0.5, twice would be 0.25.
    const std::vector<float> shadow = readExr(dir / "planar-shadow.exr").at("Y");
    size_t shadowed = 0, blendedOnce = 0;
    for (size_t k = 0; k < shadow.size(); ++k) {
        if (one.stencil[k] != 1.0f) continue;
        shadowed++;
        blendedOnce += shadow[k] == 0.5f;
    }
    CHECK(shadowed > 10000);
    CHECK(blendedOnce == shadowed);
    std::filesystem::remove_all(dir);
}

// Every hard case (docs/hard-cases.md): on the instances lying in the ground plane y = 0,
// the projected shadow is the reference's within a pixel of its boundaries; everywhere
// else planar's known failure shows, asserted: shadows that fall on anything but the
// plane (objects' own unlit sides, shadows cast on other objects) stay lit.
TEST_CASE("planar on every hard case: right on the ground plane, its known failure elsewhere") {
    for (const auto& entry : std::filesystem::directory_iterator(builtinSceneDir() + "/hard")) {
        if (entry.path().extension() != ".json") continue;
        const std::string name = entry.path().stem().string();
        const test::HardScene s(entry.path().string());
        const std::vector<float> v = s.run("planar").visibility;
        // The receivers: instances with every vertex at y = 0.
        std::vector<bool> onGround(s.scene.instances.size(), true);
        for (size_t t = 0; t < s.world.triangles.size(); ++t) {
            for (int c = 0; c < 3; ++c) {
                if (s.world.positions[s.world.triangles[t][c]].y != 0.0f) onGround[s.world.triangleInstance[t]] = false;
            }
        }
        test::Misclassified ground, elsewhere;
        for (int j = 0; j < s.gbuffer.height; ++j) {
            for (int i = 0; i < s.gbuffer.width; ++i) {
                const size_t k = s.gbuffer.index(i, j);
                if (!s.gbuffer.hit[k]) continue;
                test::Misclassified& m = onGround[s.world.triangleInstance[s.gbuffer.triangle[k]]] ? ground : elsewhere;
                m.hitPixels++;
                if (s.reference[k] == v[k]) continue;
                m.count++;
                (s.reference[k] == 1.0f ? m.falseShadow : m.falseLight)++;
                m.awayFromBoundary += !test::nearReferenceBoundary(s.gbuffer, s.reference, s.light(), i, j);
            }
        }
        INFO(name << ": ground " << ground.count << " of " << ground.hitPixels << " misclassified, " << ground.awayFromBoundary
                  << " away from a boundary; elsewhere " << elsewhere.falseLight << " false light, " << elsewhere.falseShadow
                  << " false shadow of " << elsewhere.hitPixels);
        // huge-depth-range: the reference's ray offset is about 2 cm there (a 10 km scene),
        // so its contact shadows near the camera shrink by a band several pixels wide
        // (test_shadow_volume_hard_cases.cpp shows those pixels are the reference's).
        // box-contact: 1 mm in a 566 m scene, which moves the box's shadow edges by up to a
        // pixel of its close-up (shadow-volume differs from the reference at the same pixels).
        const bool referenceOffsetCase = name == "huge-depth-range" || name == "box-contact";
        CHECK(ground.percent() <= (referenceOffsetCase ? 0.5 : kGroundBoundPercent));
        CHECK(ground.awayFromBoundary <= ground.hitPixels / (referenceOffsetCase ? 300 : 10000));
        // Never a shadow off the plane, so no false shadow there; and the failure is visible.
        CHECK(elsewhere.falseShadow == 0);
        if (elsewhere.hitPixels > 0) CHECK(elsewhere.falseLight > 0);
    }
}
