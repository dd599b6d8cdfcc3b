// raster/portable_math.h: each function within a few ulps of libm over the arguments the
// code uses, exact where it promises (integral exp2, log2 of powers of two, the special
// values), and the same bits as recorded here, so a compiler or CPU that changed any
// operation fails (libm itself changes with GLIBC_TUNABLES; these must not).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "raster/portable_exp.h"
#include "raster/portable_math.h"
#include "tests/raster/raster_test_util.h"

namespace portable = shadowlab::portable;
namespace raster = shadowlab::raster;
namespace test = shadowlab::test;

namespace {

// Distance in ulps between two finite doubles of the same sign (0 when equal).
double ulps(double a, double b) {
    if (a == b) return 0.0;
    const double scale = std::ldexp(1.0, std::ilogb(std::max({std::abs(a), std::abs(b), std::numeric_limits<double>::min()})) - 52);
    return std::abs(a - b) / scale;
}

struct Sweep {
    double from, to;
    int count;
    double at(int i) const { return from + (to - from) * i / (count - 1); }
};

// The largest error in ulps of f against g over the sweep, relative to max(|g|, floor) so
// that zeros of the function (sin at pi) are judged by the scale of the argument.
double worstUlps(const std::function<double(double)>& f, const std::function<double(double)>& g, Sweep sweep, double floor = 0.0) {
    double worst = 0.0;
    for (int i = 0; i < sweep.count; ++i) {
        const double x = sweep.at(i), expected = g(x), got = f(x);
        const double scale = std::ldexp(1.0, std::ilogb(std::max({std::abs(expected), floor, std::numeric_limits<double>::min()})) - 52);
        worst = std::max(worst, std::abs(got - expected) / scale);
    }
    return worst;
}

uint64_t hashBits(uint64_t state, double value) {
    uint64_t bits;
    std::memcpy(&bits, &value, 8);
    return (state ^ bits) * 0x100000001b3ull;
}

}  // namespace

TEST_CASE("portable sin, cos, tan, exp, log, log2, exp2, pow, atan, acos are within a few ulps of libm") {
    const Sweep angles{-40.0, 40.0, 200001};
    CHECK(worstUlps(portable::sin, [](double x) { return std::sin(x); }, angles, 1.0) <= 2.0);
    CHECK(worstUlps(portable::cos, [](double x) { return std::cos(x); }, angles, 1.0) <= 2.0);
    CHECK(worstUlps(portable::tan, [](double x) { return std::tan(x); }, {-1.5, 1.5, 100001}) <= 4.0);
    CHECK(worstUlps(portable::exp, [](double x) { return std::exp(x); }, {-700.0, 700.0, 200001}) <= 2.0);
    CHECK(worstUlps(portable::log, [](double x) { return std::log(x); }, {1e-6, 1e6, 200001}, 1.0) <= 2.0);
    CHECK(worstUlps(portable::log2, [](double x) { return std::log2(x); }, {1e-3, 1e3, 200001}, 1.0) <= 2.0);
    CHECK(worstUlps(portable::exp2, [](double x) { return std::exp2(x); }, {-60.0, 60.0, 200001}) <= 2.0);
    CHECK(worstUlps(portable::atan, [](double x) { return std::atan(x); }, {-50.0, 50.0, 200001}) <= 2.0);
    CHECK(worstUlps(portable::acos, [](double x) { return std::acos(x); }, {-1.0, 1.0, 200001}) <= 4.0);
    // pow as e^{b ln a}: about |b ln a| ulps; the code's uses (sRGB 1/2.4, shininess, splits).
    for (double b : {1.0 / 2.4, 2.0, 64.0, 0.37}) {
        INFO("b = " << b);
        CHECK(worstUlps([b](double a) { return portable::pow(a, b); }, [b](double a) { return std::pow(a, b); }, {1e-3, 1e3, 100001}) <=
              4.0 + 2.0 * std::abs(b) * 7.0);
    }
    CHECK(ulps(portable::hypot(3.0, 4.0), 5.0) == 0.0);
}

TEST_CASE("portable powFloat rounds to within one float ulp of libm's double pow") {
    // FLIP's uses: HyAB^0.7 (HyAB up to about 250), and a difference in [0, 1] to a power in [0, 1].
    for (const float b : {0.7f, 0.5f, 1.0f / 3.0f, 0.05f, 1.0f, 2.4f}) {
        double worst = 0.0;
        for (int i = 1; i <= 200000; ++i) {
            const float a = float(i) * 0.00125f;
            const float got = portable::powFloat(a, b), expected = float(std::pow(double(a), double(b)));
            worst = std::max(worst, std::abs(double(got) - double(expected)) / double(std::nextafter(expected, INFINITY) - expected));
        }
        CAPTURE(b);
        CHECK(worst <= 1.0);
    }
    CHECK(portable::powFloat(0.0f, 0.5f) == 0.0f);
    CHECK(portable::powFloat(0.0f, 0.0f) == 1.0f);
    CHECK(portable::powFloat(1.0f, 0.3f) == 1.0f);
    CHECK(portable::powFloat(4.0f, 0.5f) == 2.0f);
    CHECK(std::isnan(portable::powFloat(-1.0f, 0.5f)));
    CHECK(portable::powFloat(1e-30f, 0.5f) == doctest::Approx(1e-15f));
}

TEST_CASE("portable atan2 is within a few ulps of libm in every quadrant, with libm's signed zeros and axes") {
    double worst = 0.0;
    for (int k = 0; k < 100000; ++k) {
        const double angle = -3.2 + 6.4 * k / 99999.0, radius = 0.01 + 3.0 * (k % 17);
        const double y = radius * std::sin(angle), x = radius * std::cos(angle);
        worst = std::max(worst, ulps(portable::atan2(y, x), std::atan2(y, x)));
    }
    CHECK(worst <= 3.0);
    const double inf = std::numeric_limits<double>::infinity();
    for (double y : {0.0, -0.0, 1.0, -1.0, inf, -inf}) {
        for (double x : {0.0, -0.0, 2.0, -2.0, inf, -inf}) {
            INFO("atan2(" << y << ", " << x << ")");
            const double expected = std::atan2(y, x), got = portable::atan2(y, x);
            CHECK(ulps(got, expected) <= 1.0);
            CHECK(std::signbit(got) == std::signbit(expected));
        }
    }
    CHECK(std::isnan(portable::atan2(std::numeric_limits<double>::quiet_NaN(), 1.0)));
}

TEST_CASE("portable math is exact where it promises and keeps libm's special values") {
    for (int k = -1074; k <= 1023; ++k) {
        INFO("k = " << k);
        REQUIRE(portable::exp2(double(k)) == std::ldexp(1.0, k));
        REQUIRE(portable::log2(std::ldexp(1.0, k)) == double(k));
    }
    CHECK(portable::exp(0.0) == 1.0);
    CHECK(portable::log(1.0) == 0.0);
    CHECK(portable::sin(0.0) == 0.0);
    CHECK(portable::cos(0.0) == 1.0);
    CHECK(portable::pow(1.0, 123.5) == 1.0);
    CHECK(portable::pow(0.0, 2.0) == 0.0);
    CHECK(portable::pow(5.0, 0.0) == 1.0);
    CHECK(portable::acos(1.0) == 0.0);
    CHECK(portable::acos(-1.0) == std::acos(-1.0));
    CHECK(portable::exp(1000.0) == std::numeric_limits<double>::infinity());
    CHECK(portable::exp(-1000.0) == 0.0);
    CHECK(portable::log(0.0) == -std::numeric_limits<double>::infinity());
    CHECK(std::isnan(portable::log(-1.0)));
    CHECK(std::isnan(portable::acos(1.5)));
    CHECK(std::isnan(portable::sin(std::numeric_limits<double>::infinity())));
    CHECK(std::isnan(portable::exp(std::numeric_limits<double>::quiet_NaN())));
}

// exp scales its series by 2^k in two exact power-of-two factors: the same bits as ldexp's
// two steps, across the whole range, the subnormal results near -745 included.
TEST_CASE("portable exp scales by powers of two exactly as ldexp does, subnormal results included") {
    using namespace portable::detail;
    int subnormal = 0;
    for (int i = 0; i <= 200000; ++i) {
        const double x = -745.13 + i * ((709.78 + 745.13) / 200000.0);
        const double k = std::floor(x * kInvLn2 + 0.5);
        const double r = (x - k * kLn2High) - k * kLn2Low;
        const double series = portable::exp(r);   // |r| <= ln 2 / 2: k = 0, the series alone
        if (std::floor(r * kInvLn2 + 0.5) != 0.0) continue;
        const int half = int(k) / 2;
        const double expected = std::ldexp(std::ldexp(series, half), int(k) - half);
        subnormal += std::fpclassify(expected) == FP_SUBNORMAL;
        const double got = portable::exp(x);
        INFO("x = " << x);
        REQUIRE(std::memcmp(&expected, &got, sizeof expected) == 0);
    }
    CHECK(subnormal > 1000);
}

// The array form, at every SIMD level, against portable::exp value by value: the whole
// range, its ends, subnormal results, overflow, underflow, NaN and infinities, with a tail
// shorter than any vector.
TEST_CASE("portable expRun gives portable exp's bits at every SIMD level") {
    std::vector<double> x;
    for (int i = 0; i <= 40000; ++i) x.push_back(-800.0 + i * (1600.0 / 40000.0));
    for (double v : {0.0, -0.0, 709.782712893384, 709.7827128933841, -745.1332191019412, -745.1332191019413, 1e-300,
                     -1e-300, std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                     std::numeric_limits<double>::quiet_NaN(), 0.5 * 0.6931471805599453, -0.5 * 0.6931471805599453})
        x.push_back(v);
    for (raster::SimdLevel level : test::supportedLevels()) {
        INFO(raster::simdLevelName(level));
        std::vector<double> out(x.size(), -1.0);
        portable::expRun(level, x.data(), out.data(), x.size());
        for (size_t k = 0; k < x.size(); ++k) {
            const double expected = portable::exp(x[k]);
            INFO("x = " << x[k]);
            REQUIRE(std::memcmp(&expected, &out[k], sizeof expected) == 0);
        }
        portable::expRun(level, x.data(), x.data(), 0);   // nothing to do, nothing touched
    }
}

// The bits themselves, hashed over every function and a spread of arguments. Recorded on
// the development machine; any CPU, libm or compiler must reproduce them.
TEST_CASE("portable math gives the recorded bits") {
    uint64_t state = 0xcbf29ce484222325ull;
    for (int i = 0; i < 100000; ++i) {
        const double x = (i - 50000) * 1.234567e-3;
        for (double value : {portable::sin(x), portable::cos(x), portable::tan(x * 0.02), portable::exp(x * 0.1),
                             portable::log(std::abs(x) + 1e-3), portable::log2(std::abs(x) + 1e-3), portable::exp2(x * 0.3),
                             portable::pow(std::abs(x) + 0.5, 1.0 / 2.4), portable::atan(x), portable::acos(std::fmod(x, 1.0))})
            state = hashBits(state, value);
    }
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(state));
    CHECK(std::string(text) == "125ba6a9bc933961");
}
