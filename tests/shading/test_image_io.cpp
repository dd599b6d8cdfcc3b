// EXR round trip (bit-exact, every conventions.md channel name), PNG round trip, atomic
// writes and the errors for unreadable files, missing channels and size mismatches.
#include <algorithm>
#include <doctest/doctest.h>

#include <fstream>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>

#include <stb/stb_image.h>

#include "scenes/write_file.h"
#include "shading/image_io.h"
#include "tests/scratch_directory.h"
#include "tests/same_bits.h"

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
        CHECK(test::sameBytes(*all.find(name), *written.find(name)));
    }
    const ImageChannels some = readExr(file, {"V", "hit"});
    CHECK(some.names == std::vector<std::string>{"V", "hit"});
    CHECK(test::sameBytes(some.at("V"), written.at("V")));
}

TEST_CASE("G-buffer and radiance land in the named channels") {
    GBuffer g;
    g.width = 2;
    g.height = 1;
    g.hit = {1, 0};
    g.position = {{1.0f, 2.0f, 3.0f}, glm::vec3(0.0f)};
    g.normal = {{0.0f, 1.0f, 0.0f}, glm::vec3(0.0f)};
    g.shadingNormal = g.normal;
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

// The rename replaced what it renamed over: a link with a file, and (as root) /dev/full with a
// regular file that then took every write.
TEST_CASE("a write through a symbolic link writes the file it names, and a device is written in place") {
    ScratchDirectory dir("atomic-link");
    const fs::path file = dir.path / "target.json", link = dir.path / "link.json";
    writeTextFile(file, "old");
    fs::create_symlink(file.filename(), link);
    writeTextFile(link, "new");
    CHECK(fs::is_symlink(fs::symlink_status(link)));
    std::ifstream in(file);
    CHECK(std::string(std::istreambuf_iterator<char>(in), {}) == "new");
    std::vector<std::string> entries = dir.entries();
    std::sort(entries.begin(), entries.end());
    CHECK(entries == std::vector<std::string>{"link.json", "target.json"});   // no temporary left

    writeTextFile("/dev/null", "discarded");
    CHECK(fs::is_character_file("/dev/null"));
    if (fs::exists("/dev/full")) {
        CHECK_THROWS_AS(writeTextFile("/dev/full", std::string(1 << 16, 'x')), std::runtime_error);
        CHECK(fs::is_character_file("/dev/full"));
    }
    CHECK_THROWS_WITH_AS(writeTextFile(dir.path, "x"), doctest::Contains("is a directory"), std::runtime_error);
}

// The rename keeps the temporary's mode: it must be a new file's, as a file written in
// place gets (0666 less the umask), not mkstemp's 0600, which hid every output from other users.
TEST_CASE("a file written whole has the mode of a file written in place") {
    ScratchDirectory dir("atomic-mode");
    const fs::path inPlace = dir.path / "in-place.txt", whole = dir.path / "whole.txt";
    std::ofstream(inPlace) << "x";
    writeTextFile(whole, "x");
    CHECK(fs::status(whole).permissions() == fs::status(inPlace).permissions());
    CHECK((fs::status(whole).permissions() & fs::perms::owner_write) != fs::perms::none);
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
TEST_CASE("reading refuses images wider than 8192 pixels or with more than 32 channels") {
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
    for (int c = 0; c < 33; ++c) many.set(std::string(1, char('A' + c)), {float(c)});
    const fs::path manyFile = dir.path / "many.exr";
    writeExr(manyFile, many);
    CHECK(message(manyFile).find("33 channels, more than 32") != std::string::npos);
    many.data.pop_back(), many.names.pop_back();   // 32 channels, the most `render --aov` writes: read
    writeExr(manyFile, many);
    CHECK(readExr(manyFile).names.size() == 32);
}

namespace {

// EXR bytes by hand (OpenEXR file layout): the magic number, a version word, then
// attributes "name\0type\0" + int32 size + value, each header ended by an empty name.
std::string int32Bytes(int32_t value) { return std::string(reinterpret_cast<const char*>(&value), 4); }

std::string exrAttribute(const std::string& name, const std::string& type, int32_t size, const std::string& value = "") {
    return name + '\0' + type + '\0' + int32Bytes(size) + value;
}

std::string exrStart(int32_t versionFlags = 0) { return int32Bytes(20000630) + int32Bytes(2 | versionFlags); }

std::string parseMessage(const std::string& bytes) {
    try {
        parseExr(bytes, "crafted.exr");
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "no error";
}

}  // namespace

// OpenEXR 3.1 allocates what a header declares before reading it (the fuzz target found a
// 400-byte file that asked for 2 GB); image_io.cpp walks the headers first.
TEST_CASE("an EXR header that declares more bytes than the file holds is refused before OpenEXR reads it") {
    CHECK(parseMessage(exrStart() + exrAttribute("x", "blob", 0x7fffffff)) ==
          "EXR file 'crafted.exr': header attribute 'x' declares 2147483647 bytes, more than the 0 left in the file");
    CHECK(parseMessage(exrStart() + exrAttribute("x", "int", -4)).find("declares -4 bytes") != std::string::npos);
    const std::string tallWindow = int32Bytes(0) + int32Bytes(0) + int32Bytes(0) + int32Bytes(0x7ffffffe);
    CHECK(parseMessage(exrStart() + exrAttribute("dataWindow", "box2i", 16, tallWindow) + '\0')
              .find("data window is 1 x 2147483647 pixels; images must be 1..8192 on a side") != std::string::npos);
    // In a multi-part file (version bit 12) every part's header is walked, not only the first.
    const std::string firstPart = exrAttribute("a", "int", 4, int32Bytes(7)) + '\0';
    CHECK(parseMessage(exrStart(0x1000) + firstPart + exrAttribute("b", "blob", 1000) + '\0' + '\0')
              .find("header attribute 'b' declares 1000 bytes") != std::string::npos);
    // A known type is read by its own layout, whatever the size says: the two must agree.
    CHECK(parseMessage(exrStart() + exrAttribute("displayWindow", "box2i", 0) + tallWindow + '\0')
              .find("header attribute 'displayWindow' of type 'box2i' declares 0 bytes but holds 16") != std::string::npos);
    CHECK(parseMessage(exrStart() + exrAttribute("preview", "preview", 8, int32Bytes(40000) + int32Bytes(40000)) + '\0')
              .find("declares 8 bytes but holds a 40000 x 40000 preview") != std::string::npos);
    CHECK(parseMessage(exrStart() + exrAttribute("views", "stringvector", 8, int32Bytes(0x7fffffff) + int32Bytes(0)) + '\0')
              .find("declares 8 bytes but holds a string of 2147483647 bytes") != std::string::npos);
    CHECK(parseMessage(exrStart() + exrAttribute("channels", "chlist", 4, std::string("R\0", 2) + std::string(16, '\0') + '\0') + '\0')
              .find("declares 4 bytes but holds 18 or more") != std::string::npos);
    CHECK(parseMessage(exrStart(0x200) + exrAttribute("tiles", "tiledesc", 9, int32Bytes(4) + int32Bytes(12976132) + '\0') + '\0')
              .find("tiles of 4 x 12976132 pixels; tiles must be 1..2048 on a side") != std::string::npos);
    // A float vector is read as size / 4 floats: 7 bytes would leave the library 3 bytes behind.
    CHECK(parseMessage(exrStart() + exrAttribute("weights", "floatvector", 7, std::string(7, '\0')) + '\0')
              .find("declares 7 bytes but holds whole floats only") != std::string::npos);
    // 4 w h wraps to 0 in 64 bits for w = h = 2^31: compared by division instead.
    CHECK(parseMessage(exrStart() + exrAttribute("preview", "preview", 8, int32Bytes(int32_t(0x80000000u)) + int32Bytes(int32_t(0x80000000u))) + '\0')
              .find("holds a 2147483648 x 2147483648 preview") != std::string::npos);
    CHECK(parseMessage(exrStart() + exrAttribute("ids", "idmanifest", 4, int32Bytes(0)) + '\0').find("is an ID manifest") != std::string::npos);
    CHECK(parseMessage("ply\n" + int32Bytes(2)).find("not an EXR file (no magic number)") != std::string::npos);
    CHECK(parseMessage(std::string("\x76\x2f\x31", 3)).find("Early end of file") != std::string::npos);
    CHECK(parseMessage(exrStart() + std::string(40, 'n')).find("a header name longer than 31 bytes (the file does not set the long-names flag)") !=
          std::string::npos);
    CHECK(parseMessage(exrStart(0x400) + std::string(300, 'n')).find("a header name longer than 255 bytes") != std::string::npos);
}

TEST_CASE("an EXR's bytes in memory read as its file does") {
    ScratchDirectory dir("parse_exr");
    ImageChannels image;
    image.width = 5, image.height = 3;
    for (const char* name : {"R", "G", "B"}) {
        std::vector<float> values(image.pixelCount());
        for (size_t i = 0; i < values.size(); ++i) values[i] = float(i) * 0.25f - float(name[0]);
        image.set(name, values);
    }
    const fs::path file = dir.path / "image.exr";
    writeExr(file, image);
    std::ifstream in(file, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const ImageChannels fromMemory = parseExr(bytes, file), fromFile = readExr(file);
    CHECK(fromMemory.names == fromFile.names);
    CHECK(fromMemory.data == fromFile.data);
    for (const std::string& name : image.names) CHECK(fromMemory.at(name) == image.at(name));
    CHECK(parseMessage(bytes.substr(0, bytes.size() / 2)).find("crafted.exr") != std::string::npos);
}
