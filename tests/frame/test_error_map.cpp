// The error map of `shadowlab render --error-map`: false shadow and false light in their
// colours over the dimmed grey of the shaded image; and the scoring it shares with sweep.
#include <doctest/doctest.h>

#include <array>
#include <vector>

#include <nlohmann/json.hpp>

#include "frame/registry.h"
#include "frame/score.h"
#include "frame/score_json.h"
#include "scenes/scene_file.h"
#include "shading/tonemap.h"
#include "tests/shading/visibility_row.h"

using namespace shadowlab;
using shadowlab::test::visibilityRow;

namespace {

std::array<uint8_t, 3> pixel(const std::vector<uint8_t>& rgb, size_t k) {
    return {rgb[3 * k], rgb[3 * k + 1], rgb[3 * k + 2]};
}

}  // namespace

TEST_CASE("error map: red false shadow, blue false light, dimmed grey elsewhere") {
    // Pixels: false shadow; false light; both lit; both shadowed; background where the
    // test claims light (not scored); lit with a partial V above the threshold.
    const ImageChannels reference = visibilityRow({1, 1, 1, 1, 0, 1}, {1, 0, 1, 0, 0, 1});
    const ImageChannels test = visibilityRow({1, 1, 1, 1, 0, 1}, {0, 1, 1, 0, 1, 0.75f});
    // Radiance 3 in every channel: Reinhard maps luminance 3 to 3 / (1 + 3) = 0.75.
    const std::vector<glm::vec3> shaded(6, glm::vec3(3.0f));
    const std::vector<uint8_t> rgb = errorMapImage(reference, test, shaded);
    REQUIRE(rgb.size() == 18);
    const uint8_t grey = toSrgb8(0.75f) / 2;
    const std::array<uint8_t, 3> greyPixel{grey, grey, grey};
    CHECK(pixel(rgb, 0) == kFalseShadowColour);
    CHECK(pixel(rgb, 1) == kFalseLightColour);
    for (size_t k : {2, 3, 4, 5}) CHECK(pixel(rgb, k) == greyPixel);
    CHECK(kFalseShadowColour != kFalseLightColour);
}

TEST_CASE("error map: the counts agree with compareImages, sizes must match") {
    const ImageChannels reference = visibilityRow({1, 1, 1}, {1, 0, 0});
    const ImageChannels test = visibilityRow({1, 1, 1}, {0, 1, 1});
    const ErrorFigures figures = compareImages(reference, test);
    const std::vector<uint8_t> rgb = errorMapImage(reference, test, std::vector<glm::vec3>(3));
    size_t red = 0, blue = 0;
    for (size_t k = 0; k < 3; ++k) {
        red += pixel(rgb, k) == kFalseShadowColour;
        blue += pixel(rgb, k) == kFalseLightColour;
    }
    CHECK(red == figures.falseShadow);
    CHECK(blue == figures.falseLight);
    CHECK_THROWS_AS(errorMapImage(reference, test, std::vector<glm::vec3>(2)), std::invalid_argument);
}

TEST_CASE("scoring a frame: the reference against itself is exact, JSON carries stats and time") {
    const Scene scene = loadScene(builtinSceneDir() + "/hard/thin-occluder.json");
    const PreparedScene prepared(scene);
    const ImageChannels reference = renderReferenceImage(prepared, raster::SimdLevel::Scalar);
    FrameSettings settings;
    settings.simd = raster::SimdLevel::Scalar;
    const Frame frame = renderFrame(prepared, findTechnique("reference"), settings);
    const ErrorFigures self = scoreFrame(reference, frame);
    CHECK(self.pixels > 100000);
    CHECK(self.rms == 0.0);
    CHECK(self.misclassified() == 0);
    // The thin plate's shadow is a sliver: `none` misses it, but only a little.
    const ErrorFigures none = scoreFrame(reference, renderFrame(prepared, findTechnique("none"), settings));
    CHECK(none.falseLight > 0);
    CHECK(none.falseShadow == 0);

    Frame withStats = frame;
    withStats.shadow.stats = {{"texels", 4096}};
    const nlohmann::json j = nlohmann::json::parse(formatScoreJson("thin-occluder", "reference", "reference", {{"bias", "0"}}, withStats, self));
    CHECK(j["scene"] == "thin-occluder");
    CHECK(j["technique"] == "reference");
    CHECK(j["reference"] == "reference");
    CHECK(j["settings"]["bias"] == "0");
    CHECK(j["technique_ms"].get<double>() == frame.techniqueMs);
    CHECK(j["stats"]["texels"] == 4096);
    CHECK(j["errors"]["misclassified"] == 0);
    CHECK(j["errors"]["pixels"] == self.pixels);
}
