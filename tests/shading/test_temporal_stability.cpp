// The flicker figure (shading/temporal_stability.h): the change of a test's V between two
// frames, over the pixels where the reference's V stayed put and the surface was hit in both.
#include <cmath>
#include <limits>

#include <doctest/doctest.h>

#include "shading/temporal_stability.h"

using namespace shadowlab;

namespace {

ImageChannels image(std::vector<float> v, std::vector<float> hit) {
    ImageChannels channels;
    channels.width = int(v.size());
    channels.height = 1;
    channels.set("V", std::move(v));
    channels.set("hit", std::move(hit));
    return channels;
}

}  // namespace

TEST_CASE("flicker counts only pixels whose reference did not change and that were hit in both frames") {
    // Pixel 0: missed in frame 0; 1: the reference changes (a shadow edge moved), so the
    // test's change there is right; 2 to 5: the reference is steady; 5 by less than the tolerance.
    const ImageChannels ref0 = image({1, 1, 0, 1, 0, 0.5f}, {0, 1, 1, 1, 1, 1});
    const ImageChannels ref1 = image({1, 0, 0, 1, 0, 0.5f + 1.0f / 512}, {1, 1, 1, 1, 1, 1});
    const ImageChannels test0 = image({0, 1, 0, 1, 0.25f, 0.5f}, {1, 1, 1, 1, 1, 1});
    const ImageChannels test1 = image({1, 0, 1, 1, 0.0f, 0.5f}, {1, 1, 1, 1, 1, 1});
    const FlickerFigures f = flickerFigures(ref0, ref1, test0, test1);
    CHECK(f.pixels == 5);
    CHECK(f.stablePixels == 4);
    CHECK(f.stablePercent() == doctest::Approx(80.0));
    CHECK(f.mean == doctest::Approx((1.0 + 0.0 + 0.25 + 0.0) / 4));
    CHECK(f.p99 == 1.0);   // ceil(0.99 * 4) = 4th smallest of {0, 0, 0.25, 1}
    // With no tolerance the 1/512 change of pixel 5's reference makes it unstable.
    CHECK(flickerFigures(ref0, ref1, test0, test1, "V", 0.0f).stablePixels == 3);
}

TEST_CASE("the flicker percentile is the nearest rank, and NaN or mismatched images are not hidden") {
    std::vector<float> steady(200, 1.0f), hit(200, 1.0f), moved(200, 1.0f);
    // Two of 200 pixels change by 1: the 198th smallest (ceil(0.99 * 200)) is still 0 ...
    moved[7] = moved[99] = 0.0f;
    const ImageChannels ref = image(steady, hit), before = image(steady, hit);
    CHECK(flickerFigures(ref, ref, before, image(moved, hit)).p99 == 0.0);
    CHECK(flickerFigures(ref, ref, before, image(moved, hit)).mean == doctest::Approx(0.01));
    // ... three make it 1.
    moved[150] = 0.0f;
    CHECK(flickerFigures(ref, ref, before, image(moved, hit)).p99 == 1.0);
    // A frame identical to the one before flickers nowhere.
    const FlickerFigures still = flickerFigures(ref, ref, before, before);
    CHECK(still.mean == 0.0);
    CHECK(still.p99 == 0.0);
    CHECK(still.stablePixels == 200);
    moved[3] = std::numeric_limits<float>::quiet_NaN();
    const FlickerFigures nan = flickerFigures(ref, ref, before, image(moved, hit));
    CHECK(std::isnan(nan.mean));
    CHECK(std::isnan(nan.p99));
    CHECK_THROWS_AS(flickerFigures(ref, ref, before, image({1, 1}, {1, 1})), std::invalid_argument);
    ImageChannels noV;
    noV.width = 200, noV.height = 1;
    noV.set("hit", hit);
    CHECK_THROWS(flickerFigures(ref, ref, before, noV));
}
