// projected-texture (shadows/projected/): the ground shadow against the exact reference for
// point, spot and directional lights, the instance roles the parameters choose, and the
// method's known failures asserted as such (RTR 7.2): no self-shadowing, and a shadow cast
// backward onto a receiver between the light and its occluder.
#include <doctest/doctest.h>

#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <stdexcept>

#include "frame/registry.h"
#include "raster/thread_count.h"
#include "scenes/scene_file.h"
#include "tests/shadows/shadow_test_support.h"

using namespace shadowlab;

namespace {

// Misclassified pixels among the receivers' (the ground's), where the texture's texels
// and the camera's pixels sample the shadow's edge differently.
test::Misclassified onInstances(const test::HardScene& s, const std::vector<float>& v,
                                const std::vector<bool>& chosen) {
    test::Misclassified m;
    for (int j = 0; j < s.gbuffer.height; ++j) {
        for (int i = 0; i < s.gbuffer.width; ++i) {
            const size_t k = s.gbuffer.index(i, j);
            if (!s.gbuffer.hit[k] || !chosen[s.world.triangleInstance[s.gbuffer.triangle[k]]]) continue;
            m.hitPixels++;
            if (s.reference[k] == v[k]) continue;
            m.count++;
            (s.reference[k] == 1.0f ? m.falseShadow : m.falseLight)++;
            m.awayFromBoundary += !test::nearReferenceBoundary(s.gbuffer, s.reference, s.light(), i, j);
        }
    }
    return m;
}

std::vector<bool> groundOnly(const Scene& scene) {
    std::vector<bool> chosen;
    for (const MeshInstance& instance : scene.instances) chosen.push_back(instance.name == "ground");
    return chosen;
}

// assets/scenes/projected/backward-cast.json: a card under a point light, a receiving screen between
// them and the ground below, at a quarter of its pixels.
Scene backwardCast() {
    Scene scene = loadScene(std::string(SHADOWLAB_SOURCE_DIR) + "/assets/scenes/projected/backward-cast.json");
    scene.camera.width /= 3, scene.camera.height /= 3;
    return scene;
}

}  // namespace

// Every hard case (docs/hard-cases.md) with the default roles (the ground receives), but for
// coincident-faces, whose quads lie in the ground and so must receive too.
TEST_CASE("projected-texture: on every hard case the ground's shadow is the reference's, or one texture is refused") {
    for (const auto& entry : std::filesystem::directory_iterator(builtinSceneDir() + "/hard")) {
        if (entry.path().extension() != ".json") continue;
        const std::string name = entry.path().stem().string();
        const test::HardScene s(entry.path().string());
        if (name == "point-light-inside" || name == "light-close") {
            // Occluders all around the light (a room's walls), or beside it (a pillar's top
            // 5 cm below it): no frustum of one texture holds them.
            CHECK_THROWS_WITH_AS(s.run("projected-texture"), doctest::Contains("projected-texture: the occluders"),
                                 std::invalid_argument);
            continue;
        }
        const std::map<std::string, std::string> roles =
            name == "coincident-faces" ? std::map<std::string, std::string>{{"receivers", "ground+quad-red+quad-blue"}}
                                       : std::map<std::string, std::string>{};
        const ShadowOutputs out = s.run("projected-texture", roles);
        const test::Misclassified ground = onInstances(s, out.visibility, groundOnly(s.scene));
        INFO(name << ": " << ground.count << " of " << ground.hitPixels << " ground pixels misclassified ("
                  << ground.falseLight << " false light), " << ground.awayFromBoundary << " away from a boundary");
        CHECK(ground.hitPixels > 10000);
        if (name == "huge-depth-range") {
            // One texture over a 10 km scene: the near occluders' shadows fall between texels.
            CHECK(ground.percent() > 1.0);
            CHECK(ground.falseLight > 50 * ground.falseShadow);
            continue;
        }
        // Where texels and pixels sample a shadow's edge differently; at a grazing edge or
        // a thin shadow (box-contact, 1 mm in a 566 m scene) a texel's width from it.
        CHECK(ground.percent() <= 0.1);
        CHECK(ground.awayFromBoundary <= ground.hitPixels / 5000);
    }
}

TEST_CASE("projected-texture: no self-shadowing, an occluder's side turned from the light stays lit") {
    const test::HardScene s(test::hardCase("sphere-terminator"));
    const std::vector<float> v = s.run("projected-texture").visibility;
    size_t unlitSide = 0, unlitSideLit = 0, occluderShadowed = 0;
    for (size_t k = 0; k < s.gbuffer.pixelCount(); ++k) {
        if (!s.gbuffer.hit[k] || s.scene.instances[s.world.triangleInstance[s.gbuffer.triangle[k]]].name == "ground") {
            continue;
        }
        occluderShadowed += v[k] == 0.0f;
        if (test::facesLight(s.gbuffer, k, s.light())) continue;
        unlitSide++;
        unlitSideLit += v[k] == 1.0f;
    }
    CHECK(unlitSide > 10000);
    CHECK(unlitSideLit == unlitSide);   // the reference has V = 0 on all of them
    CHECK(occluderShadowed == 0);
}

TEST_CASE("projected-texture: a receiver between the light and the occluder gets the shadow cast backward") {
    const test::HardScene s(backwardCast());
    const ShadowOutputs out = s.run("projected-texture", {{"occluders", "card"}, {"receivers", "ground+screen"}});
    size_t screenPixels = 0, screenShadowed = 0, screenShadowedInReference = 0;
    for (size_t k = 0; k < s.gbuffer.pixelCount(); ++k) {
        if (!s.gbuffer.hit[k] || s.world.triangleInstance[s.gbuffer.triangle[k]] != 1) continue;
        screenPixels++;
        screenShadowed += out.visibility[k] == 0.0f;
        screenShadowedInReference += s.reference[k] == 0.0f;
    }
    // The card (1 m at 7 m below the light) projects to 4/7 m on the screen 4 m below it,
    // about 4% of the screen's 3 m x 3 m; the reference lights the whole screen.
    CHECK(screenPixels > 1000);
    CHECK(screenShadowedInReference == 0);
    CHECK(screenShadowed > screenPixels / 50);
    CHECK(screenShadowed < screenPixels / 10);
}

TEST_CASE("projected-texture: the parameters choose the roles, instances not chosen stay lit") {
    const test::HardScene s(backwardCast());
    // By default the ground receives and everything else occludes: the screen casts onto
    // the ground, nothing shadows the screen or the card.
    const ShadowOutputs byDefault = s.run("projected-texture");
    CHECK(test::stat(byDefault, "occluder_triangles") == 4.0);
    // Only the card occludes, only the screen receives: the ground stays lit.
    const ShadowOutputs chosen = s.run("projected-texture", {{"occluders", "card"}, {"receivers", "screen"}});
    CHECK(test::stat(chosen, "occluder_triangles") == 2.0);
    for (size_t k = 0; k < s.gbuffer.pixelCount(); ++k) {
        if (!s.gbuffer.hit[k]) continue;
        if (s.world.triangleInstance[s.gbuffer.triangle[k]] != 1) CHECK(chosen.visibility[k] == 1.0f);
    }
    CHECK(test::stat(chosen, "shadowed_receiver_pixels") > 0.0);
}

TEST_CASE("projected-texture: without a ground the largest instance receives") {
    Scene scene = backwardCast();
    scene.instances[0].name = "floor";
    const test::HardScene s(std::move(scene));
    const ShadowOutputs out = s.run("projected-texture");
    CHECK(test::stat(out, "occluder_triangles") == 4.0);   // the screen and the card
    CHECK(test::stat(out, "shadowed_receiver_pixels") > 100.0);
}

TEST_CASE("projected-texture: bad roles are refused with the names") {
    const test::HardScene s(backwardCast());
    CHECK_THROWS_WITH_AS(s.run("projected-texture", {{"occluders", "cardd"}}),
                         doctest::Contains("occluders names no instance \"cardd\" (instances: ground, screen, card)"),
                         std::invalid_argument);
    CHECK_THROWS_WITH_AS(s.run("projected-texture", {{"occluders", "card+ground"}}),
                         doctest::Contains("instance \"ground\" is both an occluder and a receiver"),
                         std::invalid_argument);
    for (const char* bad : {"", "card+", "+card", "a=b"}) {
        CHECK_THROWS_AS(s.run("projected-texture", {{"receivers", bad}}), std::invalid_argument);
    }
}

TEST_CASE("projected-texture: the same bytes for 1 and 2 threads and every SIMD level, with its buffers") {
    const test::HardScene s(test::hardCase("spot"));
    const Technique& technique = findTechnique("projected-texture");
    const TechniqueParams params(technique.name, technique.params, {});
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "shadowlab-test-projected";
    const auto runWith = [&](int threads, raster::SimdLevel level, const std::filesystem::path& debugDir) {
        return withThreads(threads, [&] {
            return technique.run({.prepared = s.prepared,
                                  .gbuffer = s.gbuffer,
                                  .light = s.scene.lights[0],
                                  .simd = level,
                                  .params = params,
                                  .debugDir = debugDir}).visibility;
        });
    };
    const std::vector<float> one = runWith(1, raster::SimdLevel::Scalar, dir);
    CHECK(one == runWith(2, raster::SimdLevel::Scalar, {}));
    for (raster::SimdLevel level : {raster::SimdLevel::Avx2, raster::SimdLevel::Avx512}) {
        if (raster::simdLevelSupported(level)) CHECK(one == runWith(2, level, {}));
    }
    for (const char* file : {"projected-texture-texture.png", "projected-texture-receivers.exr"}) {
        CHECK(std::filesystem::is_regular_file(dir / file));
    }
    std::filesystem::remove_all(dir);
}
