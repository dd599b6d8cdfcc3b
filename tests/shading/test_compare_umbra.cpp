// The umbra errors of compareImages (conventions.md, "Figures and errors"): the
// reference's umbra (V < 0.02) lit by the test above 0.1, and the reverse, its fully lit
// region (V > 0.98) shadowed by the test below 0.9; both strict, and symmetric under
// V -> 1 - V. Beside them the finer umbra lit 0.02: the full umbra (V < 0.001) lit above 0.02.
#include <doctest/doctest.h>

#include <vector>

#include <nlohmann/json.hpp>

#include "shading/compare.h"
#include "tests/shading/visibility_row.h"

using namespace shadowlab;
using shadowlab::test::visibilityRow;

namespace {

std::vector<float> mirrored(std::vector<float> v) {
    for (float& x : v) x = 1.0f - x;
    return v;
}

}  // namespace

TEST_CASE("umbra errors: counts at and around the thresholds") {
    // Reference umbra: 0, 0.01, 0.019 (0.02 itself is not umbra); fully lit: 0.99, 1, 1
    // (0.98 is not). The last pixel is background and not scored.
    const ImageChannels reference = visibilityRow({1, 1, 1, 1, 1, 1, 1, 1, 1, 0},
                                               {0, 0.01f, 0.019f, 0.02f, 0.5f, 0.98f, 0.99f, 1, 1, 0});
    const ImageChannels test = visibilityRow({1, 1, 1, 1, 1, 1, 1, 1, 1, 1},
                                          {0.1f, 0.11f, 1, 1, 0.5f, 0, 0.9f, 0.89f, 1, 1});
    const ErrorFigures f = compareImages(reference, test);
    CHECK(f.pixels == 9);
    CHECK(f.umbraPixels == 3);
    CHECK(f.umbraLit == 2);      // 0.11 and 1; 0.1 is not above the tolerance
    CHECK(f.litPixels == 3);
    CHECK(f.litShadowed == 1);   // 0.89; 0.9 is not below 1 - tolerance
    CHECK(f.umbraOver == 1);     // the test's 0 where the reference has 0.98
    CHECK(f.umbraErrors() == f.umbraLit + f.umbraOver);
    CHECK(f.percentOfPixels(f.umbraLit) == doctest::Approx(200.0 / 9.0));

    const nlohmann::json j = nlohmann::json::parse(formatJson(f));
    CHECK(j["umbra_pixels"] == 3);
    CHECK(j["lit_pixels"] == 3);
    CHECK(j["umbra_lit"] == 2);
    CHECK(j["lit_shadowed"] == 1);
    CHECK(j["umbra_over"] == 1);
    CHECK(j["umbra_errors"] == 3);
    CHECK(j["lit_shadowed_percent"].get<double>() == doctest::Approx(100.0 / 9.0));
    const std::string text = formatText(f);
    CHECK(text.find("umbra lit") != std::string::npos);
    CHECK(text.find("of 3 umbra pixels") != std::string::npos);
    CHECK(text.find("lit shadowed") != std::string::npos);
    CHECK(text.find("umbra over") != std::string::npos);
}

TEST_CASE("umbra lit 0.02: the full umbra (V < 0.001) lit above a fiftieth of the light") {
    // Reference 0, 0, 0, 0.0009, 0.001, 0.01; test 0.02, 0.021, 0.09, 1, 1, 1: the full
    // umbra is the first four (0.001 is not in it); of those, 0.021, 0.09 and 1 count (0.02
    // is not above the tolerance), and only the 1 is above the 0.1 figure's tolerance.
    const std::vector<float> hit(6, 1.0f);
    const ErrorFigures f = compareImages(visibilityRow(hit, {0, 0, 0, 0.0009f, 0.001f, 0.01f}),
                                         visibilityRow(hit, {0.02f, 0.021f, 0.09f, 1, 1, 1}));
    CHECK(f.fullUmbraPixels == 4);
    CHECK(f.fullUmbraLit == 3);
    CHECK(f.umbraPixels == 6);
    CHECK(f.umbraLit == 3);   // the last three, all above 0.1 in the wider umbra (V < 0.02)
    CHECK(f.umbraErrors() == f.umbraLit + f.umbraOver);   // not counted again among the umbra errors
    const nlohmann::json j = nlohmann::json::parse(formatJson(f));
    CHECK(j["full_umbra_pixels"] == 4);
    CHECK(j["full_umbra_lit"] == 3);
    CHECK(j["full_umbra_lit_percent"].get<double>() == doctest::Approx(50.0));
    CHECK(formatText(f).find("of 4 full umbra pixels") != std::string::npos);
}

TEST_CASE("umbra over-estimated: the test's umbra where the reference sees more than the tolerance") {
    // Reference 0.5, 0.11, 0.1, 0.5, 0.01; test 0, 0.019, 0, 0.02, 0: only the first two
    // count (0.1 is not above the tolerance, 0.02 is not umbra, 0.01 is umbra in both).
    const std::vector<float> hit(5, 1.0f);
    const ErrorFigures f =
        compareImages(visibilityRow(hit, {0.5f, 0.11f, 0.1f, 0.5f, 0.01f}), visibilityRow(hit, {0, 0.019f, 0, 0.02f, 0}));
    CHECK(f.umbraOver == 2);
    CHECK(f.umbraLit == 0);
    CHECK(f.umbraErrors() == 2);
}

TEST_CASE("umbra errors: the two directions swap when V is mirrored") {
    const std::vector<float> hit(6, 1.0f);
    const std::vector<float> referenceV = {0, 0, 0.005f, 1, 1, 0.5f};
    const std::vector<float> testV = {0.3f, 0.05f, 0.5f, 0.2f, 1, 0.7f};
    const ErrorFigures f = compareImages(visibilityRow(hit, referenceV), visibilityRow(hit, testV));
    const ErrorFigures m = compareImages(visibilityRow(hit, mirrored(referenceV)), visibilityRow(hit, mirrored(testV)));
    CHECK(f.umbraLit == 2);
    CHECK(f.litShadowed == 1);
    CHECK(m.umbraPixels == f.litPixels);
    CHECK(m.litPixels == f.umbraPixels);
    CHECK(m.umbraLit == f.litShadowed);
    CHECK(m.litShadowed == f.umbraLit);
}

TEST_CASE("umbra errors: on hard shadows they are false light and false shadow") {
    const std::vector<float> hit(6, 1.0f);
    const ErrorFigures f = compareImages(visibilityRow(hit, {0, 0, 1, 1, 0, 1}), visibilityRow(hit, {1, 0, 0, 1, 1, 0}));
    REQUIRE(f.binary);
    CHECK(f.umbraLit == f.falseLight);
    CHECK(f.litShadowed == f.falseShadow);
    CHECK(f.umbraOver == f.falseShadow);
    CHECK(f.umbraLit == 2);
    CHECK(f.litShadowed == 2);
}
