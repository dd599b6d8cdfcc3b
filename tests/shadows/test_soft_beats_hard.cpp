// Soft techniques against the hard shadow: RMS below 0.05
// against the soft reference, which the hard shadow itself meets on sphere-box, says
// nothing. Here each soft technique is held to what its design promises, on the soft cases
// of assets/scenes/soft (penumbrae of 1,000 to 5,000 pixels at 320 x 200), against the hard
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

#include <algorithm>
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
        : s(test::smallScene(std::string(SHADOWLAB_SOURCE_DIR) + "/assets/scenes/soft/" + file, 320, 200)) {
        Light centre = s.scene.lights[0];
        centre.type = LightType::Point;
        hard = ReferenceVisibility(s.world, &s.transmission).visibility(s.gbuffer, centre);
    }
    size_t penumbraPixels(const std::vector<float>& v) const {
        size_t n = 0;
        for (size_t k = 0; k < v.size(); ++k) n += s.gbuffer.hit[k] && v[k] > 0.01f && v[k] < 0.99f;
        return n;
    }
};

struct Score {
    std::vector<float> visibility;    // the run's V
    double rmsRatio, penumbraRatio;   // of the hard shadow's RMS, of the reference's penumbra pixels
};

// Runs a technique, scores it and prints the score (docs/performance.md's table: test_shadows
// -tc="soft techniques against the hard shadow*" -s | grep MESSAGE).
Score score(const HardAndSoft& h, const std::string& scene, const Run& run) {
    Score result{h.s.run(run.technique, run.params).visibility, 0.0, 0.0};
    const std::vector<float>& v = result.visibility;
    result.rmsRatio = h.s.rms(v) / h.s.rms(h.hard);
    result.penumbraRatio = double(h.penumbraPixels(v)) / double(h.penumbraPixels(h.s.reference));
    const std::string label = scene + " " + run.technique + (run.params.count("width") ? " width=pcss" : "");
    MESSAGE(label << ": RMS " << result.rmsRatio
                  << " of the hard shadow's, penumbra " << result.penumbraRatio << " of the reference's");
    return result;
}

// Width-estimating techniques: RMS at most 0.7 of the hard shadow's; a penumbra within
// `penumbraTolerance` of the reference's pixel count. Runs with a negative tolerance are
// only printed.
void checkBeatsHardClearly(const HardAndSoft& h, const std::string& scene, const std::vector<Run>& runs) {
    for (const Run& run : runs) {
        const Score s = score(h, scene, run);
        if (run.penumbraTolerance < 0.0) continue;
        CHECK(s.rmsRatio <= 0.7);
        CHECK(std::abs(s.penumbraRatio - 1.0) <= run.penumbraTolerance);
    }
}

// Fixed-width filtered maps: better than the hard shadow (measured 0.61 - 0.96 of its RMS).
void checkBeatsHard(const HardAndSoft& h, const std::string& scene) {
    for (const std::string technique : {"vsm", "esm", "evsm", "msm"}) CHECK(score(h, scene, {technique, {}, 0.0}).rmsRatio < 1.0);
}

// Outer-penumbra methods: lighter than the hard shadow (by more than 0.01) at no more than
// 0.05% of the hit pixels (measured at most 7 of about 40,000: silhouette pixels where the
// map's texels and the rays disagree); darker than it inside the reference's shadow (V <
// 0.99) at 0.4% or more (measured 0.6% for smoothies under the large light, 0.7 - 4%
// elsewhere; a technique that returned the hard shadow would have none), and where the
// reference is fully lit at no more than a quarter as many pixels (measured at most 0.12,
// penumbra maps on tilted-receiver and under the large light); RMS below twice the hard
// shadow's (measured 0.89 - 1.48). A technique that darkened everything fails both.
void checkOuterPenumbraOnly(const HardAndSoft& h, const std::string& scene) {
    for (const std::string technique : {"smoothies", "penumbra-maps"}) {
        const Score scored = score(h, scene, {technique, {}, 0.0});
        CHECK(scored.rmsRatio < 2.0);
        const std::vector<float>& v = scored.visibility;
        size_t hit = 0, lighter = 0, darkerInShadow = 0, darkerAway = 0;
        for (size_t k = 0; k < v.size(); ++k) {
            if (!h.s.gbuffer.hit[k]) continue;
            ++hit, lighter += v[k] > h.hard[k] + 0.01f;
            if (v[k] < h.hard[k] - 0.01f) ++(h.s.reference[k] < 0.99f ? darkerInShadow : darkerAway);
        }
        INFO(technique << ": " << lighter << " pixels lighter and " << darkerInShadow << " + " << darkerAway
                       << " darker than the hard shadow (inside the reference's shadow + where it is lit), of " << hit);
        CHECK(double(lighter) <= 0.0005 * double(hit));
        CHECK(double(darkerInShadow) >= 0.004 * double(hit));
        CHECK(double(darkerAway) <= 0.25 * double(darkerInShadow));
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

void checkScene(const std::string& scene, const std::vector<Run>& widthEstimating) {
    const HardAndSoft h(scene + ".json");
    checkBeatsHardClearly(h, scene, widthEstimating);
    checkBeatsHard(h, scene);
    checkOuterPenumbraOnly(h, scene);
}

// The same runs, with a negative tolerance: printed, not held to the bound.
std::vector<Run> onlyPrinted(std::vector<Run> runs, const std::vector<std::string>& techniques) {
    for (Run& run : runs)
        if (std::find(techniques.begin(), techniques.end(), run.technique) != techniques.end()) run.penumbraTolerance = -1.0;
    return runs;
}

}  // namespace

TEST_CASE("soft techniques against the hard shadow: two-boxes") { checkScene("two-boxes", kWidthEstimating); }
TEST_CASE("soft techniques against the hard shadow: torus-over-plane") { checkScene("torus-over-plane", kWidthEstimating); }
TEST_CASE("soft techniques against the hard shadow: sharp-corner") { checkScene("sharp-corner", kWidthEstimating); }

// Where the penumbra is widest, only some keep the promise: under the large light PCSS's
// blocker search misses far blockers (RMS 0.77 of the hard shadow's), fins reach 0.86, the
// width=pcss moment maps 0.79 to 1.07; on the tilted receiver fins reach 0.71 and the
// width=pcss VSM's penumbra is 0.67 of the reference's (docs/performance.md, "Soft shadows").
TEST_CASE("soft techniques against the hard shadow: large-light") {
    checkScene("large-light", onlyPrinted(kWidthEstimating, {"pcss", "fins", "vsm", "msm", "evsm"}));
}
TEST_CASE("soft techniques against the hard shadow: tilted-receiver") {
    checkScene("tilted-receiver", onlyPrinted(kWidthEstimating, {"fins", "vsm"}));
}
