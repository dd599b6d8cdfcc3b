// What a technique keeps between frames (shadows/technique_history.h) may change its memory,
// never its answer: the third frame of a still view, rendered with a FrameHistory, gives the
// bytes of a frame that stands alone (V, stencil, coloured V, radiance and every stat but the
// times), at 1 and 2 threads, and so does a frame after the camera's size or the light moved.
// And the reuse is real: in a steady state the techniques that keep their buffers allocate
// little beyond their outputs (allocation_count.h counts operator new in this program).
#include <doctest/doctest.h>

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <tbb/global_control.h>

#include "frame/registry.h"
#include "frame/render.h"
#include "shadows/filtered/soft_shadow_map.h"
#include "scenes/read_file.h"
#include "scenes/scene_file.h"
#include "tests/frame/technique_scenes.h"
#include "tests/same_bits.h"
#include "tests/steady_state/allocation_count.h"

using namespace shadowlab;

namespace {

bool endsWith(const std::string& s, const std::string& tail) {
    return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// The environment techniques under a sky, a sun's (test::runsOnASun) under the sun, the
// others on sphere-box.
std::string testSceneOf(const Technique& technique) {
    const bool environment = technique.name.rfind("env-", 0) == 0 || technique.name.rfind("reference-env", 0) == 0;
    return environment ? "environment/sphere-sky.json" : test::runsOnASun(technique) ? "hard/sun.json" : "sphere-box.json";
}

Scene smallScene(const std::string& file, int width, int height) {
    Scene scene = loadScene(std::string(SHADOWLAB_SOURCE_DIR) + "/assets/scenes/" + file);
    scene.camera.width = width;
    scene.camera.height = height;
    return scene;
}

void checkSameOutputs(const ShadowOutputs& a, const ShadowOutputs& b) {
    CHECK(test::sameBytes(a.visibility, b.visibility));
    CHECK(test::sameBytes(a.colouredVisibility, b.colouredVisibility));
    CHECK(test::sameBytes(a.radiance, b.radiance));
    CHECK(test::sameBytes(a.stencil, b.stencil));
    // Every stat but the times and the figures of what the history saved (cache_...,
    // docs/architecture.md "Stat names").
    const auto untimed = [](const std::vector<TechniqueStat>& stats) {
        std::vector<TechniqueStat> kept;
        for (const TechniqueStat& s : stats) {
            if (!endsWith(s.name, "_ms") && !s.name.starts_with("cache_")) kept.push_back(s);
        }
        return kept;
    };
    const std::vector<TechniqueStat> sa = untimed(a.stats), sb = untimed(b.stats);
    REQUIRE(sa.size() == sb.size());
    for (size_t k = 0; k < sa.size(); ++k) {
        INFO(sa[k].name);
        CHECK(sa[k].name == sb[k].name);
        CHECK(test::sameBits(sa[k].value, sb[k].value));
    }
}

void checkSameFrame(const Frame& kept, const Frame& alone) {
    REQUIRE(kept.passes.size() == alone.passes.size());
    for (size_t k = 0; k < kept.passes.size(); ++k) checkSameOutputs(kept.passes[k].shadow, alone.passes[k].shadow);
    CHECK(test::sameBytes(kept.radiance, alone.radiance));
}

// The techniques that keep their buffers between frames, with the parameters that exercise
// each kept stage (a directional light for csm's cascades and LiSPSM). `otherStages` names
// the stages that still allocate per frame beyond a tenth of the first frame; those are held
// instead to allocating at least `keptBytes` fewer in the third frame than in the first.
struct Kept {
    const char* technique;
    const char* scene;
    std::map<std::string, std::string> params;
    const char* otherStages = nullptr;
    size_t keptBytes = 0;
};

constexpr int kWidth = 320, kHeight = 200;   // the allocation test's view
constexpr size_t kSoftMapBytes = size_t(kSoftMapResolution) * kSoftMapResolution * sizeof(float);

const std::vector<Kept>& keptTechniques() {
    static const std::vector<Kept> list = {
        {"shadow-map", "sphere-box.json", {}},
        {"shadow-map", "hard/sun.json", {{"warp", "lispsm"}}},
        {"csm", "hard/sun.json", {}},
        {"shadow-map", "sphere-box.json", {{"cache", "static"}, {"fit", "scene"}}},   // the static map read in place
        {"virtual-shadow-map", "hard/sun.json", {}},
        {"virtual-shadow-map", "sphere-box.json", {}},   // the disk light's centre: six faces' mip chains
        {"projected-texture", "sphere-box.json", {}},
        {"shadow-volume", "sphere-box.json", {}},
        {"vsm", "sphere-box.json", {}},
        {"vsm", "sphere-box.json", {{"filter", "sat"}}},
        {"esm", "sphere-box.json", {}},
        {"evsm", "sphere-box.json", {}},
        {"msm", "sphere-box.json", {}},
        // The framebuffer: depth, stencil and four colour planes.
        {"planar", "sphere-box.json", {}, "split, the casters' subset regrouped per draw",
         size_t(kWidth) * kHeight * (4 + 1 + 16)},
        // The map and its linear depth.
        {"pcss", "sphere-box.json", {}, "the receivers' blocker distance and width per pixel, row scratch per task",
         2 * kSoftMapBytes},
        {"chs", "sphere-box.json", {}, "min-max hierarchy", 2 * kSoftMapBytes},
        // The map.
        {"multi-sample", "sphere-box.json", {}, "each sample's lookup's row scratch", kSoftMapBytes},
    };
    return list;
}

// Each of them at 1 and 2 threads.
std::vector<std::pair<Kept, int>> keptTechniquesAtThreads() {
    std::vector<std::pair<Kept, int>> out;
    for (const Kept& kept : keptTechniques()) {
        for (int threads : {1, 2}) out.push_back({kept, threads});
    }
    return out;
}

// Frames 1 to 3 of a still view with a history; the third checked against a frame alone. A
// temporal technique's frames depend on the ones before by design (Technique::temporal): its
// first frame is checked against a frame alone, and its third against another sequence's.
std::vector<Frame> firstThreeFrames(const PreparedScene& prepared, const Technique& technique,
                                    const std::map<std::string, std::string>& params) {
    FrameHistory history;
    FrameSettings settings;
    settings.params = params;
    settings.history = &history;
    std::vector<Frame> frames;
    for (int f = 0; f < 3; ++f) frames.push_back(renderFrame(prepared, technique, settings));
    return frames;
}

void checkThirdFrame(const PreparedScene& prepared, const Technique& technique,
                     const std::map<std::string, std::string>& params) {
    const std::vector<Frame> frames = firstThreeFrames(prepared, technique, params);
    FrameSettings alone;
    alone.params = params;
    const Frame single = renderFrame(prepared, technique, alone);
    if (!technique.temporal) return checkSameFrame(frames[2], single);
    checkSameFrame(frames[0], single);
    checkSameFrame(frames[2], firstThreeFrames(prepared, technique, params)[2]);
}

}  // namespace

// Every technique at 24 x 16 pixels (the references' rays and the slow soft techniques stay
// quick), so one that starts keeping state is held to this at once. A still view cannot show
// a buffer reused without its clear (the same triangles land on the same depths again): the
// next test changes the view.
TEST_CASE("every technique's third frame of a still view gives the bytes of a frame alone") {
    for (const Technique& technique : techniques()) {
        const PreparedScene prepared(smallScene(testSceneOf(technique), 24, 16));
        for (int threads : {1, 2}) {
            const std::string what = technique.name + " at " + std::to_string(threads) + " threads";
            INFO(what);
            const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(threads));
            checkThirdFrame(prepared, technique, {});
        }
    }
}

TEST_CASE("a kept frame after the camera's size or the light changed gives the bytes of a frame alone") {
    for (const std::pair<Kept, int>& run : keptTechniquesAtThreads()) {
        const Kept& kept = run.first;
        const int threads = run.second;
        const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(threads));
        const Technique& technique = findTechnique(kept.technique);
        PreparedScene prepared(smallScene(kept.scene, 40, 24));
        FrameHistory history;
        FrameSettings settings;
        settings.params = kept.params;
        settings.history = &history;
        renderFrame(prepared, technique, settings);
        renderFrame(prepared, technique, settings);
        Camera camera = prepared.scene().camera;
        std::vector<Light> lights = prepared.scene().lights;
        for (int change = 0; change < 3; ++change) {
            const std::string what = std::string(kept.technique) + " " + kept.scene + " change " + std::to_string(change) +
                                     " at " + std::to_string(threads) + " threads";
            INFO(what);
            if (change == 0) camera.width = 72, camera.height = 40;   // larger: the buffers grow
            if (change == 1) camera.width = 32, camera.height = 20;   // smaller
            if (change == 2) {
                if (lights[0].type == LightType::Directional) {
                    lights[0].direction = glm::normalize(lights[0].direction + glm::vec3(0.1f, 0.0f, 0.05f));
                } else {
                    lights[0].position += glm::vec3(0.3f, -0.5f, 0.2f);
                }
            }
            prepared.setCamera(camera);
            prepared.setLights(lights);
            const Frame next = renderFrame(prepared, technique, settings);
            FrameSettings alone;
            alone.params = kept.params;
            checkSameFrame(next, renderFrame(prepared, technique, alone));
        }
    }
}

// Bytes allocated by each frame's technique alone (not the G-buffer, not preparation): the
// third frame allocates its outputs and little else, at most a tenth of the first frame,
// which allocated every map, framebuffer and the rasterizer's buffers. A technique that drew
// into fresh memory again would allocate as much as its first frame. Counted at one thread:
// with more, how ranges are split depends on the scheduler, and with it how many tasks
// allocate a row scratch of their own (pcss, multi-sample), so the counts would vary.
TEST_CASE("a steady state's frame allocates little beyond its outputs") {
    const tbb::global_control oneThread(tbb::global_control::max_allowed_parallelism, 1);
    for (const Kept& kept : keptTechniques()) {
        const std::string what = std::string(kept.technique) + " " + kept.scene;
        INFO(what);
        const Technique& technique = findTechnique(kept.technique);
        const PreparedScene prepared(smallScene(kept.scene, kWidth, kHeight));
        const TechniqueParams params(technique.name, technique.params, kept.params);
        if (technique.prepare) technique.prepare(prepared, prepared, params);
        const GBuffer g = renderGBuffer(prepared.world(), prepared.scene().camera, raster::bestSimdLevel());
        TechniqueHistory history;
        const ShadowInputs in{.prepared = prepared, .gbuffer = g, .light = prepared.scene().lights.front(),
                              .simd = raster::bestSimdLevel(), .params = params, .history = &history};
        size_t bytes[3] = {}, outputBytes = 0;
        for (size_t& frameBytes : bytes) {
            test::AllocationCount count;
            const ShadowOutputs out = technique.run(in);
            frameBytes = count.bytes();
            outputBytes = (out.visibility.size() + out.stencil.size()) * sizeof(float) +
                          (out.colouredVisibility.size() + out.radiance.size()) * sizeof(glm::vec3);
        }
        CAPTURE(bytes[0]);
        CAPTURE(bytes[2]);
        CAPTURE(outputBytes);
        if (!kept.otherStages) {
            CHECK(bytes[2] <= outputBytes + bytes[0] / 10);
        } else {
            const std::string still = std::string("still allocating per frame: ") + kept.otherStages;
            INFO(still);
            CHECK(bytes[2] + kept.keptBytes <= bytes[0]);
        }
    }
}
