// Error figures and heat map on a constructed pair with known counts.
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <unistd.h>

#include "shading/compare.h"
#include "shading/tonemap.h"

using namespace shadowlab;

namespace {

ImageChannels visibilityImage(const std::vector<float>& hit, const std::vector<float>& V) {
    ImageChannels image;
    image.width = 4;
    image.height = 3;
    image.set("hit", hit);
    image.set("V", V);
    return image;
}

// 4 x 3; the last two pixels are background in the reference (10 compared pixels).
const std::vector<float> kHit = {1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 0, 0};
const std::vector<float> kReference = {1, 1, 1, 1, 0, 0, 0, 0, 1, 1, 1, 0};
// Pixels 0 and 1: false shadow; pixel 4: false light; pixel 10 differs but is background.
const std::vector<float> kBinaryTest = {0, 0, 1, 1, 1, 0, 0, 0, 1, 1, 0, 0};

}  // namespace

TEST_CASE("binary pair: 2 false shadows and 1 false light out of 10 pixels") {
    const ErrorFigures f = compareImages(visibilityImage(kHit, kReference), visibilityImage(kHit, kBinaryTest));
    CHECK(f.channel == "V");
    CHECK(f.pixels == 10);
    CHECK(f.binary);
    CHECK(f.falseShadow == 2);
    CHECK(f.falseLight == 1);
    CHECK(f.misclassified() == 3);
    CHECK(f.percentOfPixels(f.misclassified()) == doctest::Approx(30.0));
    CHECK(f.rms == doctest::Approx(std::sqrt(0.3)));
    CHECK(f.meanAbs == doctest::Approx(0.3));
    CHECK(f.maxAbs == 1.0);

    const std::string json = formatJson(f);
    CHECK(json.find("\"false_shadow\": 2") != std::string::npos);
    CHECK(json.find("\"false_light\": 1") != std::string::npos);
    CHECK(json.find("\"misclassified_percent\": 30.0") != std::string::npos);
    const std::string text = formatText(f);
    CHECK(text.find("false shadow     2 (20.0000%)") != std::string::npos);
    CHECK(text.find("false light      1 (10.0000%)") != std::string::npos);
}

TEST_CASE("soft pair: fractional errors count in RMS but only threshold crossings classify") {
    std::vector<float> test = kReference;
    test[2] = 0.75f;  // error +0.25, still lit
    test[5] = 0.5f;   // error -0.5, now counts as lit: false light
    test[8] = 0.25f;  // error +0.75, now shadowed: false shadow
    const ErrorFigures f = compareImages(visibilityImage(kHit, kReference), visibilityImage(kHit, test));
    CHECK_FALSE(f.binary);
    CHECK(f.falseShadow == 1);
    CHECK(f.falseLight == 1);
    CHECK(f.rms == doctest::Approx(std::sqrt((0.0625 + 0.25 + 0.5625) / 10.0)));
    CHECK(f.meanAbs == doctest::Approx(1.5 / 10.0));
    CHECK(f.maxAbs == 0.75);

    const std::vector<uint8_t> heat =
        errorHeatMap(visibilityImage(kHit, kReference), visibilityImage(kHit, test));
    auto pixel = [&](size_t k) { return glm::ivec3(heat[3 * k], heat[3 * k + 1], heat[3 * k + 2]); };
    CHECK(pixel(0) == glm::ivec3(0, 0, 0));                     // equal
    CHECK(pixel(2) == glm::ivec3(toSrgb8(0.25f), 0, 0));        // test darker: red
    CHECK(pixel(5) == glm::ivec3(0, 0, toSrgb8(0.5f)));         // test brighter: blue
    CHECK(pixel(11) == glm::ivec3(128, 128, 128));              // background
}

TEST_CASE("the reference's hit mask decides, sizes and channels are checked") {
    // The test image claims no geometry anywhere: still compared where the reference has hit.
    const ErrorFigures f = compareImages(visibilityImage(kHit, kReference),
                                         visibilityImage(std::vector<float>(12, 0.0f), kReference));
    CHECK(f.pixels == 10);
    CHECK(f.rms == 0.0);

    ImageChannels small;
    small.width = 2;
    small.height = 2;
    small.set("V", std::vector<float>(4, 1.0f));
    CHECK_THROWS_AS(compareImages(visibilityImage(kHit, kReference), small), std::runtime_error);
    CompareOptions radiance;
    radiance.channel = "R";
    CHECK_THROWS_AS(compareImages(visibilityImage(kHit, kReference), visibilityImage(kHit, kReference), radiance),
                    std::runtime_error);
}

TEST_CASE("compareFiles reads the first file as the reference") {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("shadowlab_test_compare_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    writeExr(dir / "reference.exr", visibilityImage(kHit, kReference));
    writeExr(dir / "test.exr", visibilityImage(kHit, kBinaryTest));
    const ErrorFigures f = compareFiles(dir / "reference.exr", dir / "test.exr");
    CHECK(f.falseShadow == 2);
    CHECK(f.falseLight == 1);
    const ErrorFigures swapped = compareFiles(dir / "test.exr", dir / "reference.exr");
    CHECK(swapped.falseShadow == 1);
    CHECK(swapped.falseLight == 2);
    std::filesystem::remove_all(dir);
}
