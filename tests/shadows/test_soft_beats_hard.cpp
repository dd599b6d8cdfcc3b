// Soft techniques against the hard shadow (issue 10, "Tests that can fail"): RMS below 0.05
// against the soft reference, which the hard shadow itself meets on sphere-box, says
// nothing. Here each soft technique is held to what its design promises, on the soft cases
// of scenes/soft (penumbrae of 1,000 to 5,000 pixels at 320 x 200), against the hard
// reference (the disk's centre as a point light) and the soft one:
//   - width-estimating techniques (PCSS, the filtered maps with width=pcss, fins,
//     multi-sample) beat the hard shadow clearly: RMS at most 0.7 of the hard shadow's, and
//     a penumbra (pixels with 0.01 < V < 0.99) about the reference's size;
//   - fixed-width filtered maps (RTR 7.7: the kernel does not follow the light's size) are
//     still better than the hard shadow, but not clearly;
//   - outer-penumbra methods (smoothies, penumbra maps: RTR 7.6, Chan and Durand 2003,
//     Wyman and Hansen 2003) keep the hard umbra and only darken outside it: never lighter
//     than the hard shadow, so their RMS may exceed the hard shadow's (measured 0.9 - 1.5).
#include <doctest/doctest.h>

#include <map>
#include <string>
#include <vector>

#include "tests/shadows/soft_test_support.h"

using namespace shadowlab;

namespace {

using Params = std::map<std::string, std::string>;

struct Run {
    std::string technique;
    Params params;
    double penumbraTolerance;   // allowed |count / reference count - 1|; < 0: not checked
};

struct HardAndSoft {
    test::SoftScene s;
    std::vector<float> hard;   // V of the disk's centre as a point light
    explicit HardAndSoft(const std::string& file)
        : s(test::smallScene(std::string(SHADOWLAB_SOURCE_DIR) + "/scenes/soft/" + file, 320, 200)) {
        Light centre = s.scene.lights[0];
        centre.type = LightType::Point;
        hard = ReferenceVisibility(s.world).visibility(s.gbuffer, centre);
    }
    size_t penumbraPixels(const std::vector<float>& v) const {
        size_t n = 0;
        for (size_t k = 0; k < v.size(); ++k) n += s.gbuffer.hit[k] && v[k] > 0.01f && v[k] < 0.99f;
        return n;
    }
};

// Width-estimating techniques: RMS at most 0.7 of the hard shadow's; a penumbra within
// `penumbraTolerance` of the reference's pixel count.
void checkBeatsHardClearly(const HardAndSoft& h, const std::vector<Run>& runs) {
    const double hardRms = h.s.rms(h.hard);
    const double referencePenumbra = double(h.penumbraPixels(h.s.reference));
    for (const Run& run : runs) {
        const std::vector<float> v = h.s.run(run.technique, run.params).visibility;
        const double ratio = h.s.rms(v) / hardRms, penumbra = double(h.penumbraPixels(v)) / referencePenumbra;
        const std::string label = run.technique + (run.params.empty() ? "" : " width=pcss");
        INFO(label << ": RMS " << ratio << " of the hard shadow's, penumbra "
                           << penumbra << " of the reference's " << referencePenumbra << " pixels");
        CHECK(ratio <= 0.7);
        CHECK(std::abs(penumbra - 1.0) <= run.penumbraTolerance);
    }
}

// Fixed-width filtered maps: better than the hard shadow (measured 0.61 - 0.96 of its RMS).
void checkBeatsHard(const HardAndSoft& h) {
    for (const std::string technique : {"vsm", "esm", "evsm", "msm"}) {
        const double ratio = h.s.rms(h.s.run(technique).visibility) / h.s.rms(h.hard);
        INFO(technique << ": RMS " << ratio << " of the hard shadow's");
        CHECK(ratio < 1.0);
    }
}

// Outer-penumbra methods: lighter than the hard shadow (by more than 0.01) at no more than
// 0.05% of the hit pixels (measured at most 7 of about 40,000: silhouette pixels where the
// map's texels and the rays disagree), and darker than it around its edge at 0.4% or more
// (measured 0.6% for smoothies under the large light, 0.7 - 4% elsewhere; a technique
// that returned the hard shadow would have none).
void checkOuterPenumbraOnly(const HardAndSoft& h) {
    for (const std::string technique : {"smoothies", "penumbra-maps"}) {
        const std::vector<float> v = h.s.run(technique).visibility;
        size_t hit = 0, lighter = 0, darker = 0;
        for (size_t k = 0; k < v.size(); ++k) {
            if (!h.s.gbuffer.hit[k]) continue;
            ++hit, lighter += v[k] > h.hard[k] + 0.01f, darker += v[k] < h.hard[k] - 0.01f;
        }
        INFO(technique << ": " << lighter << " pixels lighter and " << darker << " darker than the hard shadow, of " << hit);
        CHECK(double(lighter) <= 0.0005 * double(hit));
        CHECK(double(darker) >= 0.004 * double(hit));
    }
}

// The width-estimating runs. MSM and EVSM with width=pcss spread a faint tail around the
// penumbra (their moment bounds are not sharp: Peters and Klein 2015, section 4), counted
// as penumbra pixels: measured up to 1.35 times the reference's count.
const std::vector<Run> kWidthEstimating = {
    {"pcss", {}, 0.3},
    {"multi-sample", {}, 0.3},
    {"fins", {}, 0.3},
    {"vsm", {{"filter", "sat"}, {"width", "pcss"}}, 0.3},
    {"msm", {{"filter", "sat"}, {"width", "pcss"}}, 0.45},
    {"evsm", {{"filter", "sat"}, {"width", "pcss"}, {"positive-exponent", "3"}, {"negative-exponent", "3"}}, 0.45},
};

}  // namespace

TEST_CASE("soft techniques against the hard shadow: two-boxes") {
    const HardAndSoft h("two-boxes.json");
    checkBeatsHardClearly(h, kWidthEstimating);
    checkBeatsHard(h);
    checkOuterPenumbraOnly(h);
}

TEST_CASE("soft techniques against the hard shadow: torus-over-plane") {
    const HardAndSoft h("torus-over-plane.json");
    checkBeatsHardClearly(h, kWidthEstimating);
    checkBeatsHard(h);
    checkOuterPenumbraOnly(h);
}

TEST_CASE("soft techniques against the hard shadow: sharp-corner") {
    const HardAndSoft h("sharp-corner.json");
    checkBeatsHardClearly(h, kWidthEstimating);
    checkBeatsHard(h);
    checkOuterPenumbraOnly(h);
}

// Where the penumbra is widest, only some keep the promise: PCSS's blocker search misses
// far blockers under the large light (RMS 0.77 of the hard shadow's), fins reach 0.86 and
// 0.71, the width=pcss moment maps 0.79 to 1.07 (see the README, "Soft shadows").
TEST_CASE("soft techniques against the hard shadow: large-light and tilted-receiver") {
    const HardAndSoft large("large-light.json");
    checkBeatsHardClearly(large, {{"multi-sample", {}, 0.3}});
    checkBeatsHard(large);
    checkOuterPenumbraOnly(large);
    const HardAndSoft tilted("tilted-receiver.json");
    checkBeatsHardClearly(tilted, {{"multi-sample", {}, 0.3}, {"pcss", {}, 0.3}, {"msm", {{"filter", "sat"}, {"width", "pcss"}}, 0.3}});
    checkBeatsHard(tilted);
    checkOuterPenumbraOnly(tilted);
}
