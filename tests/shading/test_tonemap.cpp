// sRGB encoding at known points of IEC 61966-2-1, rounding of every 8-bit code, and the
// tone operators.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>

#include "shading/tonemap.h"

using namespace shadowlab;

TEST_CASE("sRGB encoding at known points") {
    CHECK(srgbEncode(0.0) == 0.0);
    CHECK(srgbEncode(1.0) == doctest::Approx(1.0).epsilon(1e-15));
    CHECK(srgbEncode(0.001) == doctest::Approx(0.01292).epsilon(1e-12));      // linear segment
    CHECK(srgbEncode(0.5) == doctest::Approx(0.735356983).epsilon(1e-9));
    CHECK(srgbEncode(0.18) == doctest::Approx(0.461356129).epsilon(1e-9));
    // The two pieces meet at 0.0031308 -> 0.04045 (to the 5 digits the standard gives).
    CHECK(srgbEncode(0.0031308) == doctest::Approx(0.04045).epsilon(1e-4));
    CHECK(srgbEncode(std::nextafter(0.0031308, 1.0)) == doctest::Approx(0.04045).epsilon(1e-4));

    CHECK(toSrgb8(0.0f) == 0);
    CHECK(toSrgb8(1.0f) == 255);
    CHECK(toSrgb8(0.5f) == 188);    // 187.516
    CHECK(toSrgb8(0.18f) == 118);   // 117.646
    CHECK(toSrgb8(0.001f) == 3);    // 3.295
    CHECK(toSrgb8(7.0f) == 255);    // clamped
    CHECK(toSrgb8(-1.0f) == 0);
    CHECK(toSrgb8(std::numeric_limits<float>::quiet_NaN()) == 0);
}

TEST_CASE("sRGB decoding is the standard's EOTF, and 8-bit images decode code by code") {
    CHECK(srgbDecode(0.0) == 0.0);
    CHECK(srgbDecode(0.04) == doctest::Approx(0.04 / 12.92).epsilon(1e-15));   // linear segment
    CHECK(srgbDecode(0.5) == doctest::Approx(std::pow(0.555 / 1.055, 2.4)).epsilon(1e-14));
    CHECK(srgbDecode(1.0) == doctest::Approx(1.0).epsilon(1e-14));
    const std::vector<glm::vec3> linear = linearFromSrgb8({0, 128, 255, 255, 0, 0});
    REQUIRE(linear.size() == 2);
    CHECK(linear[0] == glm::vec3(0.0f, float(srgbDecode(128.0 / 255.0)), float(srgbDecode(1.0))));
    CHECK(linear[1].r == float(srgbDecode(1.0)));
}

TEST_CASE("every 8-bit code round-trips through the sRGB decoding") {
    for (int code = 0; code <= 255; ++code) {
        CAPTURE(code);
        CHECK(toSrgb8(float(srgbDecode(code / 255.0))) == code);
    }
}

TEST_CASE("tone operators: clamp, Reinhard on luminance, exposure in stops") {
    const glm::vec3 clamped = toneMap({2.0f, 0.5f, -1.0f}, {0.0f, ToneOperator::Clamp});
    CHECK(clamped == glm::vec3(1.0f, 0.5f, 0.0f));
    // Grey of luminance 1 -> 1 / (1 + 1); the same after halving and one stop up.
    const glm::vec3 grey = toneMap(glm::vec3(1.0f), {0.0f, ToneOperator::Reinhard});
    CHECK(grey.r == doctest::Approx(0.5f));
    CHECK(grey.g == doctest::Approx(0.5f));
    CHECK(toneMap(glm::vec3(0.5f), {1.0f, ToneOperator::Reinhard}).b == doctest::Approx(0.5f));
    // Hue is kept: the channel ratios survive.
    const glm::vec3 c = toneMap({0.4f, 0.2f, 0.1f}, {0.0f, ToneOperator::Reinhard});
    CHECK(c.r / c.g == doctest::Approx(2.0f));
    const std::vector<uint8_t> bytes = toSrgb8Image({glm::vec3(1.0f), glm::vec3(0.0f)}, {});
    CHECK(bytes == std::vector<uint8_t>{188, 188, 188, 0, 0, 0});
}
