// confidence-reprojection (Scherzer et al. 2007): without jitter a still view's frames are
// shadow-map's own test, bit for bit; with it the staircase of a coarse map sharpens over the
// frames towards the exact shadow, and the change from frame to frame dies down.
#include <doctest/doctest.h>

#include <cmath>
#include <map>
#include <string>

#include "frame/registry.h"
#include "frame/score.h"
#include "shading/compare.h"
#include "temporal_test_support.h"

using namespace shadowlab;
using namespace shadowlab::temporal_test;

namespace {

using Params = std::map<std::string, std::string>;

struct Sequence {
    FrameHistory history;
    FrameSettings settings;
    explicit Sequence(const Params& params) {
        settings.params = params;
        settings.history = &history;
    }
};

double misclassifiedPercent(const ImageChannels& reference, const Frame& frame) {
    const ErrorFigures e = scoreFrame(reference, frame);
    return e.percentOfPixels(e.misclassified());
}

}  // namespace

TEST_CASE("confidence-reprojection without jitter is shadow-map's test on every frame of a still view") {
    const PreparedScene prepared(loadSmall("sphere-box.json", 64, 40));
    Sequence plain(Params{{"resolution", "256"}});
    Sequence confidence(Params{{"resolution", "256"}, {"jitter", "off"}});
    for (int f = 0; f < 3; ++f) {
        const Frame a = renderFrame(prepared, findTechnique("shadow-map"), plain.settings);
        const Frame b = renderFrame(prepared, findTechnique("confidence-reprojection"), confidence.settings);
        REQUIRE(a.shadow.visibility == b.shadow.visibility);
    }
}

TEST_CASE("confidence-reprojection sharpens a coarse map's shadow over the frames of a still view") {
    // At 128 texels a texel is ~8 cm on the ground, 2.5 pixels: the plain map's staircase
    // misclassifies the edge's pixels. Over 48 jittered frames each pixel's history is led by
    // the tests made near a texel's centre, which are exact: at least 3 times fewer
    // misclassified pixels, and the last frames change V far less than the first.
    const PreparedScene prepared(loadSmall("sphere-box.json", 160, 100));
    const ImageChannels reference = renderReferenceImage(prepared, raster::bestSimdLevel());
    const Params coarse = {{"resolution", "128"}};
    FrameSettings alone;
    alone.params = coarse;
    const double plain = misclassifiedPercent(reference, renderFrame(prepared, findTechnique("shadow-map"), alone));
    Sequence sequence(coarse);
    std::vector<std::vector<float>> frames;
    Frame last;
    for (int f = 0; f < 48; ++f) {
        last = renderFrame(prepared, findTechnique("confidence-reprojection"), sequence.settings);
        frames.push_back(last.shadow.visibility);
    }
    const double sharpened = misclassifiedPercent(reference, last);
    INFO("shadow-map " << plain << "%, confidence-reprojection after 48 frames " << sharpened << "%");
    CHECK(plain > 0.1);
    CHECK(sharpened < plain / 3.0);
    const auto change = [&](size_t t) {
        double sum = 0.0;
        for (size_t k = 0; k < frames[t].size(); ++k) sum += std::abs(frames[t][k] - frames[t - 1][k]);
        return sum / double(frames[t].size());
    };
    CHECK(change(47) < change(1) / 4.0);
}
