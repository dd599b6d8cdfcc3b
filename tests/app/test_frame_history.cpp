// What a technique keeps from frame to frame (shadows/technique_history.h, frame/render.h's
// FrameHistory) and how the timing protocol hands it on (app/common/timing.h): a still
// view's warm-up frames bring it to a steady state and every measured frame starts there; a
// path's frame starts every run from what the frame before left and passes its own on.
// A technique that counts its frames in its state shows, as V, which frame of its sequence
// each light's pass was.
#include <doctest/doctest.h>

#include <stdexcept>
#include <string>

#include "app/common/timing.h"
#include "frame/registry.h"
#include "scenes/read_file.h"
#include "scenes/scene_file.h"

using namespace shadowlab;

namespace {

struct FrameCount {
    int frames = 0;
};

// V = the number of frames this light's pass has seen in its history, this one included.
Technique countingTechnique(const std::string& name = "counting") {
    return {.name = name,
            .description = "counts its frames",
            .params = {},
            .run = [](const ShadowInputs& in) {
                const int frames = ++in.kept().state<FrameCount>().frames;
                ShadowOutputs out;
                out.visibility.assign(in.gbuffer.pixelCount(), float(frames));
                return out;
            }};
}

Scene smallScene(const char* file) {
    Scene scene = loadScene(std::string(SHADOWLAB_SOURCE_DIR) + "/assets/scenes/" + file);
    scene.camera.width = 8;
    scene.camera.height = 5;
    return scene;
}

float countSeen(const Frame& frame, size_t pass = 0) { return frame.passes.at(pass).shadow.visibility.front(); }

}  // namespace

TEST_CASE("a frame history keeps each light's state from one frame to the next") {
    const PreparedScene prepared(smallScene("many-lights/three-lights.json"));
    REQUIRE(prepared.scene().lights.size() == 3);
    const Technique counting = countingTechnique();
    FrameHistory history;
    FrameSettings settings;
    settings.history = &history;
    for (int frame = 1; frame <= 3; ++frame) {
        const Frame f = renderFrame(prepared, counting, settings);
        for (size_t light = 0; light < 3; ++light) CHECK(countSeen(f, light) == float(frame));
    }
    // Without a history every frame is a first one.
    CHECK(countSeen(renderFrame(prepared, counting, {})) == 1.0f);
    CHECK(countSeen(renderFrame(prepared, counting, {})) == 1.0f);
}

TEST_CASE("a frame history refuses a frame of another technique, settings or scene") {
    const PreparedScene prepared(smallScene("sphere-box.json"));
    const PreparedScene other(smallScene("sphere-box.json"));
    const Technique counting = countingTechnique();
    FrameHistory history;
    FrameSettings settings;
    settings.history = &history;
    renderFrame(prepared, counting, settings);
    CHECK_THROWS_AS(renderFrame(prepared, countingTechnique("other"), settings), std::logic_error);
    CHECK_THROWS_AS(renderFrame(other, counting, settings), std::logic_error);
    FrameSettings shadowMap = settings;
    FrameHistory mapHistory;
    shadowMap.history = &mapHistory;
    renderFrame(prepared, findTechnique("shadow-map"), shadowMap);
    shadowMap.params = {{"resolution", "64"}};
    CHECK_THROWS_AS(renderFrame(prepared, findTechnique("shadow-map"), shadowMap), std::logic_error);
    // The refused frames left the history as it was.
    CHECK(countSeen(renderFrame(prepared, counting, settings)) == 2.0f);
}

TEST_CASE("a standalone frame's copies of its inputs share one history") {
    const PreparedScene prepared(smallScene("sphere-box.json"));
    const GBuffer g = renderGBuffer(prepared.world(), prepared.scene().camera, raster::SimdLevel::Scalar);
    const TechniqueParams params("counting", {}, {});
    const ShadowInputs in{.prepared = prepared, .gbuffer = g, .light = prepared.scene().lights.front(),
                          .simd = raster::SimdLevel::Scalar, .params = params};
    const ShadowInputs copy = in;
    ++in.kept().state<FrameCount>().frames;
    CHECK(copy.kept().state<FrameCount>().frames == 1);
    CHECK(in.kept().size() == 1);
}

TEST_CASE("a still view's measured frames start from the steady state its warm-up frames leave") {
    const PreparedScene prepared(smallScene("sphere-box.json"));
    const Technique counting = countingTechnique();
    const ProgressStage frames(nullptr, "frames", 5);
    // Two warm-up frames, then each of three measured frames is the third of its sequence.
    const TimedFrames warm = timeFrames(prepared, counting, {}, 2, 3, frames);
    CHECK(countSeen(warm.last) == 3.0f);
    // Without warm-up frames each measured frame is a first frame.
    CHECK(countSeen(timeFrames(prepared, counting, {}, 0, 3, frames).last) == 1.0f);
}

TEST_CASE("a path's frame starts every run from the frame before and passes its own on") {
    const PreparedScene prepared(smallScene("sphere-box.json"));
    const Technique counting = countingTechnique();
    const ProgressStage frames(nullptr, "frames", 20);
    FrameHistory path;
    FrameSettings settings;
    settings.history = &path;
    for (int frame = 1; frame <= 3; ++frame) {
        // However many warm-up and measured runs, each is the path's frame-th frame.
        const TimedFrames timed = timeFrames(prepared, counting, settings, 2, 3, frames);
        CHECK(countSeen(timed.last) == float(frame));
    }
    CHECK(countSeen(renderFrame(prepared, counting, settings)) == 4.0f);
}
