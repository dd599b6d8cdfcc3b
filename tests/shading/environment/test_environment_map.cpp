// Environment maps (shading/environment/environment_map.h, environment_file.h): the
// direction mapping of conventions.md on known directions and round trips, the rotation,
// exact solid angles, and reading EXR (DWAB) and Radiance HDR files, bad ones refused.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "raster/portable_constants.h"
#include "shading/environment/environment_file.h"
#include "shading/image_io.h"
#include "tests/scratch_directory.h"
#include "tests/shading/environment/shipped_maps.h"

using namespace shadowlab;

namespace {

double distance(const glm::dvec3& a, const glm::dvec3& b) { return glm::length(a - b); }

// A Radiance HDR file's bytes: the header, "-Y h +X w", then the scanlines as given.
std::string radianceFile(int width, int height, const std::string& scanlines, const std::string& extraHeader = "") {
    return "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n" + extraHeader + "\n-Y " + std::to_string(height) + " +X " +
           std::to_string(width) + "\n" + scanlines;
}

// One run-length scanline of width w (>= 8): every channel a run of w copies of its byte.
std::string rleScanline(int w, uint8_t r, uint8_t g, uint8_t b, uint8_t e) {
    std::string s = {char(2), char(2), char(w >> 8), char(w & 255)};
    for (uint8_t c : {r, g, b, e}) s += {char(128 + w), char(c)};
    return s;
}

}  // namespace

TEST_CASE("environment map: the lat-long mapping of conventions.md on known directions") {
    const EnvironmentMap map = constantEnvironment(64, 32, glm::vec3(1.0f));
    // u = 0.5 + atan2(d.x, -d.z) / (2 pi), v = acos(d.y) / pi.
    CHECK(map.coordinates({0.0, 0.0, -1.0}).x == doctest::Approx(0.5));    // -Z: the centre column
    CHECK(map.coordinates({1.0, 0.0, 0.0}).x == doctest::Approx(0.75));    // +X
    CHECK(map.coordinates({-1.0, 0.0, 0.0}).x == doctest::Approx(0.25));   // -X
    CHECK(map.coordinates({0.0, 0.0, 1.0}).x == doctest::Approx(0.0));     // +Z: the seam
    CHECK(map.coordinates({0.0, 1.0, 0.0}).y == 0.0);                      // zenith: row 0
    CHECK(map.coordinates({0.0, -1.0, 0.0}).y == doctest::Approx(1.0));    // nadir: the last row
    CHECK(map.coordinates({1.0, 0.0, 0.0}).y == doctest::Approx(0.5));     // horizon
    CHECK(map.texelToward({0.0, 1.0, 0.0}).y == 0);
    CHECK(map.texelToward({0.0, -1.0, 0.0}).y == 31);
    CHECK(map.texelToward({1.0, -0.01, 0.0}) == glm::ivec2(48, 16));
    CHECK(map.texelToward({1e-9, 0.0, 1.0}).x == 63);   // just past the seam, on the last column
    // Direction length does not matter; u stays in [0, 1).
    CHECK(distance(glm::dvec3(map.coordinates({0.0, 0.0, -5.0}), 0.0), glm::dvec3(0.5, 0.5, 0.0)) < 1e-15);
    for (double u : {0.0, 0.1, 0.37, 0.5, 0.75, 0.999}) {
        for (double v : {0.01, 0.25, 0.5, 0.8, 0.99}) {
            INFO("u = " << u << ", v = " << v);
            const glm::dvec3 d = map.direction(u, v);
            CHECK(std::abs(glm::length(d) - 1.0) < 1e-15);
            const glm::dvec2 back = map.coordinates(d);
            CHECK(std::abs(back.x - u) < 1e-14);
            CHECK(std::abs(back.y - v) < 1e-14);
        }
    }
}

TEST_CASE("environment map: a rotation turns the map about +Y, counter-clockwise seen from above") {
    EnvironmentMap map = constantEnvironment(64, 32, glm::vec3(1.0f));
    map.rotationRadians = 0.5 * kPi;
    // The map's -Z column (u = 0.5) now looks along R_y(90 deg) (0, 0, -1) = (-1, 0, 0).
    CHECK(distance(map.direction(0.5, 0.5), {-1.0, 0.0, 0.0}) < 1e-15);
    CHECK(map.coordinates({-1.0, 0.0, 0.0}).x == doctest::Approx(0.5));
    // World -Z is where the map's +X column (u = 0.75) turned to.
    CHECK(map.coordinates({0.0, 0.0, -1.0}).x == doctest::Approx(0.75));
    map.rotationRadians = -7.0;   // any angle, wrapped
    const glm::dvec2 uv = map.coordinates(map.direction(0.3, 0.6));
    CHECK(uv.x == doctest::Approx(0.3));
    CHECK(uv.y == doctest::Approx(0.6));
}

TEST_CASE("environment map: texel solid angles are the exact areas, summing to 4 pi") {
    for (const glm::ivec2 size : {glm::ivec2(2, 1), glm::ivec2(64, 32), glm::ivec2(1024, 512), glm::ivec2(30, 7)}) {
        const int w = size.x, h = size.y;
        const EnvironmentMap map = constantEnvironment(w, h, glm::vec3(1.0f));
        double total = 0.0;
        for (int j = 0; j < h; ++j) total += map.texelSolidAngle(j) * w;
        INFO(w << " x " << h);
        CHECK(std::abs(total - 4.0 * kPi) < 1e-12);
        // A row's area is the zone 2 pi (cos theta0 - cos theta1), split evenly by the columns.
        const int j = h / 2;
        CHECK(map.texelSolidAngle(j) ==
              doctest::Approx(2.0 * kPi * (std::cos(kPi * j / h) - std::cos(kPi * (j + 1) / h)) / w).epsilon(1e-13));
    }
}

TEST_CASE("environment files: the shipped EXR (DWAB) and Radiance HDR of one map agree, negatives clamped") {
    const EnvironmentMap exr = readEnvironmentMap(kMaps / "pmndrs_sky.exr");
    const EnvironmentMap hdr = readEnvironmentMap(kMaps / "pmndrs_sky.hdr");
    REQUIRE(exr.width == 512);
    REQUIRE(exr.height == 256);
    REQUIRE(hdr.width == exr.width);
    REQUIRE(hdr.height == exr.height);
    // The HDR was made from the EXR with negatives clamped (assets/environments/LICENSE.md);
    // RGBE keeps 8 bits of mantissa per channel against the texel's largest, so a channel
    // above a tenth of its texel's largest agrees within 2^-7 relative. Equal rows also say
    // both files are read zenith first.
    size_t compared = 0, agree = 0;
    float smallest = 1.0f;
    for (size_t k = 0; k < exr.radiance.size(); ++k) {
        const glm::vec3 a = exr.radiance[k], b = hdr.radiance[k];
        smallest = std::min({smallest, a.r, a.g, a.b});
        const float largest = std::max({a.r, a.g, a.b});
        for (int c = 0; c < 3; ++c) {
            if (a[c] < 0.1f * largest || a[c] < 1e-3f) continue;
            ++compared;
            agree += std::abs(a[c] - b[c]) <= 0x1p-7f * largest;
        }
    }
    CHECK(smallest == 0.0f);   // the file rings to -3394 around the sun
    CHECK(compared > exr.radiance.size());
    CHECK(agree == compared);
}

TEST_CASE("environment files: Radiance HDR scanlines flat and run-length, RGBE decoded at the step's centre, EXPOSURE divided out") {
    // (m + 0.5) 2^(E - 136): m = 127, E = 129 is 127.5 / 128; E = 0 is black.
    const std::string flat = std::string("\x7f\x00\x40\x81", 4) + std::string("\x10\x20\x30\x00", 4);
    const EnvironmentMap a = parseEnvironmentMap(radianceFile(2, 1, flat), "flat.hdr");
    CHECK(a.at(0, 0) == glm::vec3(127.5f / 128.0f, 0.5f / 128.0f, 64.5f / 128.0f));
    CHECK(a.at(1, 0) == glm::vec3(0.0f));
    const EnvironmentMap b = parseEnvironmentMap(radianceFile(8, 2, rleScanline(8, 127, 0, 64, 129) + rleScanline(8, 1, 2, 3, 136)),
                                                 "rle.hdr");
    CHECK(b.at(7, 0) == a.at(0, 0));
    CHECK(b.at(3, 1) == glm::vec3(1.5f, 2.5f, 3.5f));
    const EnvironmentMap c = parseEnvironmentMap(radianceFile(2, 1, flat, "EXPOSURE=2\nEXPOSURE=0.25\n"), "exposed.hdr");
    CHECK(c.at(0, 0) == a.at(0, 0) * 2.0f);   // stored values were multiplied by 2 x 0.25
}

TEST_CASE("environment files: bad files are errors that name the file") {
    const auto fails = [](const std::filesystem::path& path, const std::string& part) {
        INFO(path << ": " << part);
        try {
            readEnvironmentMap(path);
            FAIL("no error");
        } catch (const std::runtime_error& e) {
            CHECK(std::string(e.what()).find(path.string()) != std::string::npos);
            CHECK(std::string(e.what()).find(part) != std::string::npos);
        }
    };
    const test::ScratchDirectory dir("environment_files");
    const auto scratch = [&](const std::string& name) { return dir.path / name; };
    const auto hdr = [&](const std::string& name, const std::string& bytes) {
        std::ofstream(scratch(name), std::ios::binary) << bytes;
        return scratch(name);
    };
    fails(scratch("missing.exr"), "missing.exr");
    fails(hdr("eight-bit.hdr", "\x89PNG\r\n\x1a\n not radiance"), "neither OpenEXR nor Radiance HDR");
    // Cut inside the scanline header, after it (stb_image 2.27 spins forever there), inside
    // flat pixels, inside a run-length channel, and far too short for its rows.
    // (A first row of literal runs, 40 bytes, keeps the file above the fewest bytes two rows
    // need, so the second row's reads meet the end.)
    std::string literalRow = {char(2), char(2), char(0), char(8)};
    for (int c = 0; c < 4; ++c) literalRow += char(8) + std::string(8, char(100 + c));
    CHECK(parseEnvironmentMap(radianceFile(8, 1, literalRow), "literal.hdr").at(3, 0).r == doctest::Approx(100.5 * 0x1p-33));
    fails(hdr("cut-header.hdr", radianceFile(8, 2, literalRow + "\x02\x02")), "truncated (at byte");
    fails(hdr("cut-after-header.hdr", radianceFile(8, 2, literalRow + "\x02\x02\x00\x08")), "truncated (at byte");
    fails(hdr("cut-run.hdr", radianceFile(8, 2, literalRow + rleScanline(8, 1, 2, 3, 4).substr(0, 9))), "truncated (at byte");
    fails(hdr("cut-flat.hdr", radianceFile(4, 1, "\x10\x20\x30\x81\x10")), "truncated");
    fails(hdr("overrun.hdr", radianceFile(8, 1, std::string("\x02\x02\x00\x08\x89\x01", 6) + std::string(16, '\x01'))), "overruns");
    fails(hdr("zero-run.hdr", radianceFile(8, 1, std::string("\x02\x02\x00\x08\x00", 5) + std::string(16, '\x01'))), "overruns");
    fails(hdr("too-short.hdr", radianceFile(8, 1000, rleScanline(8, 1, 2, 3, 4))), "too few bytes for 1000 scanlines");
    fails(hdr("orientation.hdr", "#?RADIANCE\n\n+Y 2 +X 4\n"), "is not '-Y H +X W'");
    fails(hdr("huge.hdr", "#?RADIANCE\n\n-Y 2 +X 9000\n"), "1 to 8192 a side");
    fails(hdr("format.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 1 +X 2\n"), "unsupported FORMAT=32-bit_rle_xyze");
    fails(hdr("exposure.hdr", "#?RADIANCE\nEXPOSURE=-1\n\n-Y 1 +X 2\n"), "EXPOSURE must be a positive number");
    fails(hdr("no-end.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n"), "truncated");
    ImageChannels image;
    image.width = 4, image.height = 2;
    for (const char* name : {channel::R, channel::G, channel::B}) image.set(name, std::vector<float>(8, 1.0f));
    std::vector<float> r(8, 1.0f);
    r[5] = std::nanf("");
    image.set(channel::R, r);
    writeExr(scratch("nan.exr"), image);
    fails(scratch("nan.exr"), "texel (1, 1) is not finite");
    ImageChannels narrow;
    narrow.width = 1, narrow.height = 1;
    for (const char* name : {channel::R, channel::G, channel::B}) narrow.set(name, {1.0f});
    writeExr(scratch("narrow.exr"), narrow);
    fails(scratch("narrow.exr"), "fewer than 2 x 1");
    ImageChannels noBlue;
    noBlue.width = 2, noBlue.height = 1;
    for (const char* name : {channel::R, channel::G}) noBlue.set(name, {1.0f, 1.0f});
    writeExr(scratch("no-blue.exr"), noBlue);
    fails(scratch("no-blue.exr"), "no-blue.exr");
}

TEST_CASE("environment files: negative texels of an EXR are clamped to 0, the rest kept exactly") {
    const test::ScratchDirectory dir("environment_negative");
    const auto scratch = [&](const std::string& name) { return dir.path / name; };
    ImageChannels image;
    image.width = 4, image.height = 2;
    image.set(channel::R, {1.0f, -2.0f, 3.5f, 0.0f, -0.0f, 7.25f, 1e-30f, 2.0f});
    image.set(channel::G, std::vector<float>(8, 0.5f));
    image.set(channel::B, std::vector<float>(8, -1e-3f));
    writeExr(scratch("negative.exr"), image);
    const EnvironmentMap map = readEnvironmentMap(scratch("negative.exr"), 1.0);
    CHECK(map.rotationRadians == 1.0);
    CHECK(map.at(0, 0) == glm::vec3(1.0f, 0.5f, 0.0f));
    CHECK(map.at(1, 0) == glm::vec3(0.0f, 0.5f, 0.0f));
    CHECK(map.at(1, 1).r == 7.25f);
    CHECK(map.at(2, 1).r == 1e-30f);
}
