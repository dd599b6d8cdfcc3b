// ray-traced's denoiser setting (shadows/raytraced/ray_denoising.h): each denoiser, run by the
// technique over a still sequence, gives the same bytes at 1 and 2 threads and lowers one
// ray's error against reference-soft; a view that changes size reads its history rightly.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include <tbb/global_control.h>

#include "../temporal/temporal_test_support.h"
#include "frame/registry.h"
#include "frame/score.h"

using namespace shadowlab;
using namespace shadowlab::temporal_test;

namespace {

// Frames 0 to frames - 1 of a still view of `prepared` at `threads` threads.
std::vector<Frame> stillSequence(const PreparedScene& prepared, const std::string& denoiser, int frames, int threads) {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(threads));
    FrameHistory history;
    FrameSettings settings;
    settings.params = {{"denoiser", denoiser}};
    settings.history = &history;
    std::vector<Frame> out;
    for (int f = 0; f < frames; ++f) out.push_back(renderFrame(prepared, findTechnique("ray-traced"), settings));
    return out;
}

}  // namespace

TEST_CASE("ray-traced's denoisers: the same bytes at 1 and 2 threads, and less error than one raw ray") {
    // square-over-plane's disk light at 96 x 60, one ray a pixel: frame 5 of a still view.
    const PreparedScene prepared(loadSmall("soft/square-over-plane.json", 96, 60));
    const ImageChannels reference = renderReferenceImage(prepared, raster::bestSimdLevel(), "reference-soft");
    const double raw = scoreFrame(reference, stillSequence(prepared, "none", 6, 2).back()).rms;
    for (const char* denoiser : {"svgf", "tiled", "penumbra"}) {
        INFO(denoiser);
        const std::vector<Frame> two = stillSequence(prepared, denoiser, 6, 2);
        const std::vector<Frame> one = stillSequence(prepared, denoiser, 6, 1);
        for (size_t f = 0; f < two.size(); ++f) REQUIRE(one[f].shadow.visibility == two[f].shadow.visibility);
        const double denoised = scoreFrame(reference, two.back()).rms;
        INFO("raw RMS " << raw << ", denoised " << denoised);
        CHECK(denoised < raw / 1.5);
    }
}

TEST_CASE("ray-traced's denoisers read the frame before through a view that changed size") {
    // The history has the previous image's size, which the reprojection reads it at (a history
    // of any other size is a logic error: requireHistoryOf).
    PreparedScene prepared(loadSmall("soft/square-over-plane.json", 48, 30));
    FrameHistory history;
    FrameSettings settings;
    settings.params = {{"denoiser", "tiled"}};
    settings.history = &history;
    renderFrame(prepared, findTechnique("ray-traced"), settings);
    Camera larger = prepared.scene().camera;
    larger.width = 64, larger.height = 40;
    prepared.setCamera(larger);
    const Frame next = renderFrame(prepared, findTechnique("ray-traced"), settings);
    CHECK(next.shadow.visibility.size() == 64u * 40u);
}
