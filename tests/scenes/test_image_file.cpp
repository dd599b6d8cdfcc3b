// The one checked path for the files a user names (scenes/read_file.h) and for 8-bit
// images (scenes/image_file.h): a file's type is checked before it is opened, only PNG and
// (where allowed) JPEG are decoded, other formats are refused by name, and a truncated
// file is refused instead of decoded in part.
#include <doctest/doctest.h>

#include <sys/stat.h>

#include <stb_image_write.h>

#include "scenes/image_file.h"
#include "scenes/read_file.h"
#include "tests/scenes/scene_test_files.h"

using namespace shadowlab;
using test::checkMessage;
using test::sceneErrorOf;

namespace {

const std::string kBlinds = std::string(SHADOWLAB_SOURCE_DIR) + "/assets/textures/blinds.png";

std::string bytesOf(const std::string& path) { return readWholeFile(path); }

// A 4 x 2 RGB JPEG, written by stb_image_write.
std::string smallJpeg() {
    std::string bytes;
    const std::vector<uint8_t> rgb(4 * 2 * 3, 200);
    stbi_write_jpg_to_func([](void* to, void* data, int size) { static_cast<std::string*>(to)->append(static_cast<char*>(data), size_t(size)); },
                           &bytes, 4, 2, 3, rgb.data(), 90);
    return bytes;
}

}  // namespace

TEST_CASE("reading files: a FIFO, a device or a directory is refused before it is opened") {
    const test::TempDir dir;
    REQUIRE(mkfifo(dir.path("pipe").c_str(), 0600) == 0);
    // Opening the FIFO for reading would block this test until a writer came.
    checkMessage(sceneErrorOf([&] { readWholeFile(dir.path("pipe")); }), {"pipe: is a FIFO (named pipe), not a file"});
    checkMessage(sceneErrorOf([&] { readWholeFile("/dev/zero"); }), {"/dev/zero: is a character device, not a file"});
    checkMessage(sceneErrorOf([&] { readWholeFile(dir.path("")); }), {"is a directory, not a file"});
    checkMessage(sceneErrorOf([&] { readWholeFile(dir.path("none")); }), {"none: cannot open: No such file"});
    CHECK(readWholeFile(dir.write("a.txt", "abc")) == "abc");
}

TEST_CASE("8-bit images: PNG, and JPEG where allowed, every other format refused by name") {
    const test::TempDir dir;
    const DecodedImage blinds = readImage(kBlinds, 3, {ImageFormat::Png});
    CHECK(blinds.width > 0);
    CHECK(blinds.bytes.size() == size_t(blinds.width) * size_t(blinds.height) * 3);
    const std::string jpeg = dir.write("small.jpg", smallJpeg());
    const DecodedImage decoded = readImage(jpeg, 3, {ImageFormat::Png, ImageFormat::Jpeg});
    CHECK(decoded.width == 4);
    CHECK(decoded.height == 2);
    checkMessage(sceneErrorOf([&] { readImage(jpeg, 3, {ImageFormat::Png}); }), {"small.jpg: is a JPEG image; here only PNG is read"});
    // Headers that promise 64 x 64 pixels the files do not hold: stb_image 2.27 spins for
    // ever on the run-length HDR and returns pixels it never wrote for the TGA and the PPM.
    const std::vector<std::pair<std::string, std::string>> others{
        {"short.hdr", std::string("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 64 +X 64\n\x02\x02\x00\x40\x80", 47)},
        {"short.tga", std::string("\0\0\x02\0\0\0\0\0\0\0\0\0\x40\0\x40\0\x18\0\x80\x80", 20)},
        {"short.ppm", "P6\n64 64\n255\n\x80\x80"},
        {"a.gif", "GIF89a\x40\0\x40\0"},
        {"a.bmp", "BM\x36\0\0\0"},
        {"a.exr", std::string("v/1\x01\x02\0\0\0", 8)}};
    const std::vector<std::string> named{"is a Radiance HDR image", "is not an image this program reads", "is a PNM image",
                                         "is a GIF image", "is a BMP image", "is an OpenEXR image"};
    for (size_t k = 0; k < others.size(); ++k) {
        const std::string path = dir.write(others[k].first, others[k].second);
        checkMessage(sceneErrorOf([&] { readImage(path, 3, {ImageFormat::Png, ImageFormat::Jpeg}); }),
                     {others[k].first + ": " + named[k], "here only PNG or JPEG is read"});
    }
}

TEST_CASE("8-bit images: a truncated PNG or JPEG is refused, not decoded in part") {
    const test::TempDir dir;
    const std::string png = bytesOf(kBlinds), jpeg = smallJpeg();
    for (const size_t keep : {png.size() / 2, png.size() - 1}) {
        const std::string path = dir.write("cut.png", png.substr(0, keep));
        checkMessage(sceneErrorOf([&] { readImage(path, 3, {ImageFormat::Png}); }), {"cut.png: is truncated: a PNG file ends with its IEND chunk"});
    }
    const std::string path = dir.write("cut.jpg", jpeg.substr(0, jpeg.size() - 10));
    checkMessage(sceneErrorOf([&] { readImage(path, 3, {ImageFormat::Jpeg}); }), {"cut.jpg: is truncated: a JPEG file ends with its end-of-image marker"});
}
