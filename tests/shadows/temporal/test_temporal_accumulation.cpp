// Temporal accumulation (shadows/temporal/accumulation.h, temporal_accumulation.h): on a
// still view a temporal technique converges to its own non-temporal limit, the mean of its
// frames, and its flicker falls towards 0; a history the reprojection rejects is started
// afresh; `temporal=off` is the technique as it was.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "frame/registry.h"
#include "shadows/temporal/reprojection.h"
#include "temporal_test_support.h"

using namespace shadowlab;
using namespace shadowlab::temporal_test;

namespace {

using Params = std::map<std::string, std::string>;

// `frames` frames of a still view in one sequence: each frame's V.
std::vector<std::vector<float>> stillFrames(const PreparedScene& prepared, const std::string& technique,
                                            const Params& params, int frames) {
    FrameHistory history;
    FrameSettings settings;
    settings.params = params;
    settings.history = &history;
    std::vector<std::vector<float>> out;
    for (int f = 0; f < frames; ++f) out.push_back(renderFrame(prepared, findTechnique(technique), settings).shadow.visibility);
    return out;
}

Params with(Params p, const Params& more) {
    for (const auto& [k, v] : more) p[k] = v;
    return p;
}

struct TemporalCase {
    const char* scene;
    const char* technique;
    Params noisy;   // the per-frame noise the accumulation averages
};

const TemporalCase kTemporalCases[] = {
    {"sphere-box.json", "shadow-map", {{"filter", "poisson"}, {"poisson-rotation", "ign"}, {"poisson-radius", "3"}}},
    {"soft/square-over-plane.json", "pcss", {{"rotation", "ign"}, {"filter-taps", "8"}}},
};

}  // namespace

TEST_CASE("on a still view, accumulation without clamping is the running mean of the frames") {
    // Blending at 1 / n is the running mean while n is under the cap: after N frames each
    // pixel is the mean of the N frames' own V (the non-temporal limit), up to float rounding
    // of N blends (bound 1e-5).
    constexpr int kFrames = 24;
    for (const TemporalCase& c : kTemporalCases) {
        INFO(c.technique);
        const PreparedScene prepared(loadSmall(c.scene, 48, 30));
        const std::vector<std::vector<float>> plain = stillFrames(prepared, c.technique, c.noisy, kFrames);
        const std::vector<std::vector<float>> accumulated = stillFrames(
            prepared, c.technique,
            with(c.noisy, {{"temporal", "on"}, {"temporal-frames", "64"}, {"temporal-clamp", "off"}}), kFrames);
        REQUIRE(accumulated[0] == plain[0]);   // a sequence's first frame is the technique's own
        CHECK(plain[1] != plain[0]);           // the noise moves with the frame
        double worst = 0.0;
        for (size_t k = 0; k < plain[0].size(); ++k) {
            double mean = 0.0;
            for (const auto& frame : plain) mean += frame[k];
            mean /= kFrames;
            worst = std::max(worst, std::abs(mean - double(accumulated.back()[k])));
        }
        CHECK(worst < 1e-5);
    }
}

TEST_CASE("on a still view, a temporal technique's flicker falls towards 0") {
    // Frame t changes a pixel by (V_t - mean) / t: the change from frame to frame falls as
    // 1 / t, at the cap (temporal-frames) it stays at 1 / cap of the noise. Clamped to the
    // neighbourhood (the default) it falls all the same on a still view.
    constexpr int kFrames = 32;
    for (const TemporalCase& c : kTemporalCases) {
        INFO(c.technique);
        const PreparedScene prepared(loadSmall(c.scene, 48, 30));
        const std::vector<std::vector<float>> plain = stillFrames(prepared, c.technique, c.noisy, kFrames);
        const std::vector<std::vector<float>> v =
            stillFrames(prepared, c.technique, with(c.noisy, {{"temporal", "on"}, {"temporal-frames", "64"}}), kFrames);
        const double noise = meanChange(plain[kFrames - 1], plain[kFrames - 2]);
        const double early = meanChange(v[2], v[1]), late = meanChange(v[kFrames - 1], v[kFrames - 2]);
        INFO("noise " << noise << ", frame 2 " << early << ", frame " << kFrames - 1 << " " << late);
        CHECK(noise > 1e-3);               // the plain technique flickers
        CHECK(late < early / 6.0);         // 1/t: 1/31 against 1/2, with room for the clamp
        CHECK(late < noise / 10.0);
        CHECK(late < 1.0 / 255.0);         // under one step of an 8-bit display
    }
}

TEST_CASE("temporal=off is the technique as it was, and temporal=on starts disoccluded pixels afresh") {
    const Scene base = loadSmall("flythrough/sliding-sphere.json", 64, 40);
    PreparedScene prepared{Scene(base)};
    const Params noisy = {{"filter", "poisson"}, {"poisson-rotation", "ign"}};
    FrameHistory off, on, plainHistory;
    const auto settingsOf = [](const Params& p, FrameHistory* h) {
        FrameSettings s;
        s.params = p;
        s.history = h;
        return s;
    };
    const Technique& map = findTechnique("shadow-map");
    for (int f = 0; f < 3; ++f) {
        placeAtPathFrame(prepared, base, f, 12);
        const std::optional<PreviousView> before =
            on.previousView() ? std::optional<PreviousView>(*on.previousView()) : std::nullopt;
        const Frame plain = renderFrame(prepared, map, settingsOf(noisy, &plainHistory));
        const Frame explicitOff = renderFrame(prepared, map, settingsOf(with(noisy, {{"temporal", "off"}}), &off));
        const Frame temporal = renderFrame(prepared, map, settingsOf(with(noisy, {{"temporal", "on"}}), &on));
        CHECK(explicitOff.shadow.visibility == plain.shadow.visibility);
        if (f == 0) {
            CHECK(temporal.shadow.visibility == plain.shadow.visibility);
            continue;
        }
        // The reprojection the technique ran, again: each rejected pixel is this frame's own V.
        const Reprojection r = reproject(temporal.gbuffer, *before, {});
        CHECK(r.rejectedPixels > 10);   // the sphere moves 0.5 m a frame: ground uncovered behind it
        size_t hits = 0, keptChanged = 0;
        for (size_t k = 0; k < temporal.gbuffer.pixelCount(); ++k) {
            hits += temporal.gbuffer.hit[k];
            keptChanged += r.kept[k] && temporal.shadow.visibility[k] != plain.shadow.visibility[k];
        }
        CHECK(double(r.rejectedPixels) < 0.2 * double(hits));   // the rest of the view keeps its history
        CHECK(keptChanged > 100);                               // and blends it in
        double stat = -1.0;
        for (const TechniqueStat& s : temporal.shadow.stats)
            if (s.name == "history_rejected_pixels") stat = s.value;
        CHECK(stat == double(r.rejectedPixels));
        for (size_t k = 0; k < temporal.gbuffer.pixelCount(); ++k) {
            if (temporal.gbuffer.hit[k] && !r.kept[k]) REQUIRE(temporal.shadow.visibility[k] == plain.shadow.visibility[k]);
        }
    }
}

TEST_CASE("temporal accumulation refuses bad settings") {
    const PreparedScene prepared(loadSmall("sphere-box.json", 16, 10));
    FrameSettings settings;
    settings.params = {{"temporal", "on"}, {"temporal-frames", "0"}};
    CHECK_THROWS_AS(renderFrame(prepared, findTechnique("shadow-map"), settings), std::invalid_argument);
    settings.params = {{"temporal", "on"}, {"temporal-clamp", "median"}};
    CHECK_THROWS_AS(renderFrame(prepared, findTechnique("pcss"), settings), std::invalid_argument);
}
