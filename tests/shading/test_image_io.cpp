// EXR round trip (bit-exact, every conventions.md channel name), PNG round trip, atomic
// writes and the errors for unreadable files, missing channels and size mismatches.
#include <doctest/doctest.h>

#include <cstring>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>

#include <stb/stb_image.h>

#include "shading/image_io.h"
#include "tests/scratch_directory.h"

using namespace shadowlab;
namespace fs = std::filesystem;

namespace {

using test::ScratchDirectory;

const std::vector<std::string> kAllChannels = {"R",   "G",   "B",   "P.x", "P.y",   "P.z",    "N.x",
                                               "N.y", "N.z", "hit", "V",   "depth", "stencil"};

ImageChannels testImage() {
    ImageChannels image;
    image.width = 5;
    image.height = 3;
    const float special[] = {0.0f, -0.0f, 1.0f / 3.0f, std::numeric_limits<float>::denorm_min(),
                             std::numeric_limits<float>::max(), -1e-30f, 12345.678f};
    for (size_t c = 0; c < kAllChannels.size(); ++c) {
        std::vector<float> values(image.pixelCount());
        for (size_t k = 0; k < values.size(); ++k) {
            values[k] = special[(k + c) % std::size(special)] + float(c) * float(k % 2);
        }
        image.set(kAllChannels[c], values);
    }
    return image;
}

bool bitEqual(const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

}  // namespace

TEST_CASE("EXR write then read is bit-exact for every conventions.md channel") {
    ScratchDirectory dir("exr_roundtrip");
    const fs::path file = dir.path / "aov.exr";
    const ImageChannels written = testImage();
    writeExr(file, written);
    CHECK(dir.entries() == std::vector<std::string>{"aov.exr"});  // no temporary left

    const ImageChannels all = readExr(file);
    CHECK(all.width == 5);
    CHECK(all.height == 3);
    CHECK(all.names.size() == kAllChannels.size());
    for (const std::string& name : kAllChannels) {
        CAPTURE(name);
        REQUIRE(all.find(name) != nullptr);
        CHECK(bitEqual(*all.find(name), *written.find(name)));
    }
    const ImageChannels some = readExr(file, {"V", "hit"});
    CHECK(some.names == std::vector<std::string>{"V", "hit"});
    CHECK(bitEqual(some.at("V"), written.at("V")));
}

TEST_CASE("G-buffer and radiance land in the named channels") {
    GBuffer g;
    g.width = 2;
    g.height = 1;
    g.hit = {1, 0};
    g.position = {{1.0f, 2.0f, 3.0f}, glm::vec3(0.0f)};
    g.normal = {{0.0f, 1.0f, 0.0f}, glm::vec3(0.0f)};
    g.material = {0, 0};
    g.triangle = {4, kNoTriangle};
    g.depth = {0.25f, 1.0f};
    ImageChannels image;
    setGBuffer(image, g);
    setRadiance(image, {{0.5f, 0.25f, 0.125f}, glm::vec3(0.0f)});
    CHECK(image.at("P.z") == std::vector<float>{3.0f, 0.0f});
    CHECK(image.at("N.y") == std::vector<float>{1.0f, 0.0f});
    CHECK(image.at("hit") == std::vector<float>{1.0f, 0.0f});
    CHECK(image.at("depth") == std::vector<float>{0.25f, 1.0f});
    CHECK(image.at("B") == std::vector<float>{0.125f, 0.0f});
    CHECK_THROWS_AS(image.set("V", {1.0f}), std::invalid_argument);  // size mismatch
}

TEST_CASE("PNG write then read gives the same bytes, row 0 at the top") {
    ScratchDirectory dir("png_roundtrip");
    const fs::path file = dir.path / "image.png";
    std::vector<uint8_t> rgb(4 * 3 * 3);
    for (size_t k = 0; k < rgb.size(); ++k) rgb[k] = uint8_t(k * 7);
    writePng(file, 4, 3, rgb);
    int w = 0, h = 0, channels = 0;
    unsigned char* pixels = stbi_load(file.c_str(), &w, &h, &channels, 3);
    REQUIRE(pixels != nullptr);
    CHECK(w == 4);
    CHECK(h == 3);
    CHECK(std::vector<uint8_t>(pixels, pixels + rgb.size()) == rgb);
    stbi_image_free(pixels);
    CHECK(dir.entries() == std::vector<std::string>{"image.png"});
}

TEST_CASE("a failed write leaves neither the file nor a temporary") {
    ScratchDirectory dir("atomic");
    const fs::path file = dir.path / "report.json";
    // The writer produces part of the file, then fails.
    CHECK_THROWS_AS(writeFileAtomically(file,
                                        [](const fs::path& temporary) {
                                            std::ofstream(temporary) << "{\"half\":";
                                            throw std::runtime_error("disk full");
                                        }),
                    std::runtime_error);
    CHECK(dir.entries().empty());
    // An existing file survives a failed overwrite untouched.
    writeTextFile(file, "old");
    CHECK_THROWS(writeFileAtomically(file, [](const fs::path&) { throw std::runtime_error("no"); }));
    CHECK(dir.entries() == std::vector<std::string>{"report.json"});
    std::ifstream in(file);
    CHECK(std::string(std::istreambuf_iterator<char>(in), {}) == "old");
    // A directory that does not exist: the error names the file.
    const fs::path nowhere = dir.path / "missing" / "aov.exr";
    try {
        writeExr(nowhere, testImage());
        FAIL("writeExr into a missing directory did not throw");
    } catch (const std::runtime_error& e) {
        CHECK(std::string(e.what()).find(nowhere.string()) != std::string::npos);
    }
    CHECK_FALSE(fs::exists(dir.path / "missing"));
}

TEST_CASE("reading errors name the file and the channel") {
    ScratchDirectory dir("read_errors");
    const fs::path garbage = dir.path / "garbage.exr";
    writeTextFile(garbage, "this is not an OpenEXR file");
    for (const fs::path& path : {garbage, dir.path / "absent.exr"}) {
        try {
            readExr(path);
            FAIL("readExr did not throw");
        } catch (const std::runtime_error& e) {
            CHECK(std::string(e.what()).find(path.string()) != std::string::npos);
        }
    }
    const fs::path file = dir.path / "aov.exr";
    writeExr(file, testImage());
    try {
        readExr(file, {"V", "Z"});
        FAIL("readExr did not throw for a missing channel");
    } catch (const std::runtime_error& e) {
        CHECK(std::string(e.what()).find("'Z'") != std::string::npos);
        CHECK(std::string(e.what()).find(file.string()) != std::string::npos);
    }
    CHECK_THROWS_AS(readExr(file).at("Z"), std::runtime_error);
}

// Buffers are sized from the header: a header larger than shadowlab's images is refused
// before anything is allocated (a data window of 2^31 x 2^31 would otherwise be allocated).
TEST_CASE("reading refuses images wider than 8192 pixels or with more than 16 channels") {
    ScratchDirectory dir("read_limits");
    const auto message = [](const fs::path& path) {
        try {
            readExr(path);
        } catch (const std::runtime_error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    ImageChannels wide;
    wide.width = 8193, wide.height = 1;
    wide.set("V", std::vector<float>(wide.pixelCount(), 1.0f));
    const fs::path wideFile = dir.path / "wide.exr";
    writeExr(wideFile, wide);
    CHECK(message(wideFile).find("data window is 8193 x 1 pixels; images must be 1..8192 on a side") != std::string::npos);
    ImageChannels many;
    many.width = many.height = 1;
    for (int c = 0; c < 17; ++c) many.set(std::string(1, char('A' + c)), {float(c)});
    const fs::path manyFile = dir.path / "many.exr";
    writeExr(manyFile, many);
    CHECK(message(manyFile).find("17 channels, more than 16") != std::string::npos);
    many.data.pop_back(), many.names.pop_back();   // 16 channels: read
    writeExr(manyFile, many);
    CHECK(readExr(manyFile).names.size() == 16);
}
