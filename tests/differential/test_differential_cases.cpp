// The built-in compositing cases beyond the room (differential/outdoor_case.h,
// photo_case.h, environment_dome.h, differential/scene/photo_calibration.h): the dome holds the upper
// hemisphere's solid angle and faces its centre; the outdoor photograph is the panorama
// through the pinhole; the calibrated camera projects the board's corners where OpenCV does;
// the squares read from the real photograph alternate like a checkerboard; bad files refused;
// the cases `composite` names (differential/builtin_cases.h) build from the data folder.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <algorithm>
#include <numbers>
#include <stdexcept>

#include "differential/builtin_cases.h"
#include "differential/environment_dome.h"
#include "differential/outdoor_case.h"
#include "differential/photo_case.h"
#include "scenes/camera.h"
#include "scenes/obj_reader.h"
#include "scenes/scene_file.h"
#include "shading/environment/environment_file.h"

using namespace shadowlab;

namespace {

const std::string kPhotos = builtinDataDir() + "/photos/";

Mesh bunny() { return readObj(builtinDataDir() + "/meshes/bunny_low.obj"); }

std::string scratchFile(const std::string& name, const std::string& text) {
    const std::filesystem::path path = std::filesystem::temp_directory_path() / ("shadowlab-cases-" + name);
    std::ofstream(path) << text;
    return path.string();
}

}  // namespace

TEST_CASE("environment dome: the upper hemisphere's solid angle, every patch facing the centre with its block's light") {
    const EnvironmentMap map = readEnvironmentMap(builtinDataDir() + "/environments/blender_forest.exr");
    const double R = 200.0;
    const std::vector<PatchSurface> dome = environmentDome(map, 32, 8, R);
    REQUIRE(dome.size() == 256);
    double solidAngle = 0.0;
    for (const PatchSurface& p : dome) {
        const glm::dvec3 n = glm::cross(p.edgeU, p.edgeV);
        const glm::dvec3 centre = p.origin + 0.5 * (p.edgeU + p.edgeV);
        solidAngle += glm::length(n) / (R * R);
        REQUIRE(glm::dot(n, centre) < 0.0);
        REQUIRE(glm::length(centre) == doctest::Approx(R).epsilon(1e-9));
        REQUIRE(centre.y > 0.0);
        REQUIRE(p.emitted.size() == 1);
        REQUIRE(p.reflectance == glm::dvec3(0.0));
    }
    CHECK(solidAngle == doctest::Approx(2.0 * std::numbers::pi).epsilon(1e-9));
    CHECK_THROWS_AS(environmentDome(map, 3, 8, R), std::invalid_argument);
    CHECK_THROWS_AS(environmentDome(map, 32, 0, R), std::invalid_argument);
    CHECK_THROWS_AS(environmentDome(map, 32, 8, 0.0), std::invalid_argument);
}

TEST_CASE("environment dome: the patches hold the map's light above the horizon however finely it is cut") {
    // A 16 x 8 map of varied radiance, so that blocks finer than its texels, and blocks across
    // texel edges, must share texels.
    EnvironmentMap map = constantEnvironment(16, 8, glm::vec3(0.0f));
    for (size_t k = 0; k < map.radiance.size(); ++k) map.radiance[k] = glm::vec3(float(1 + k % 7), float(k % 3), 2.0f);
    glm::dvec3 above(0.0);   // sum of L dOmega over the texels above the horizon
    for (int j = 0; j < map.height / 2; ++j) {
        for (int i = 0; i < map.width; ++i) above += glm::dvec3(map.at(i, j)) * map.texelSolidAngle(j);
    }
    const double R = 50.0;
    for (const glm::ivec2 cut : {glm::ivec2(4, 1), glm::ivec2(16, 4), glm::ivec2(20, 3), glm::ivec2(64, 16)}) {
        glm::dvec3 held(0.0);
        for (const PatchSurface& p : environmentDome(map, cut.x, cut.y, R)) {
            held += p.emitted[0] * (glm::length(glm::cross(p.edgeU, p.edgeV)) / (R * R));
        }
        INFO(cut.x << " x " << cut.y << " patches");
        for (int c = 0; c < 3; ++c) CHECK(held[c] == doctest::Approx(above[c]).epsilon(1e-9));
    }
}

TEST_CASE("outdoor case: the photograph is the panorama through the pinhole, over a ground the camera stands on") {
    const EnvironmentMap map = readEnvironmentMap(builtinDataDir() + "/environments/blender_forest.exr");
    OutdoorSettings settings;
    settings.width = 64, settings.height = 40;
    const CompositingScene scene = compositingOutdoor(map, bunny(), settings);
    REQUIRE(scene.background.size() == 64u * 40u);
    const PixelRays rays(scene.camera);
    for (int j = 0; j < 40; j += 7) {
        for (int i = 0; i < 64; i += 9) {
            const glm::ivec2 t = map.texelToward(rays(i, j).direction);
            REQUIRE(scene.background[size_t(j) * 64 + size_t(i)] == map.at(t.x, t.y));
        }
    }
    const PatchSurface& ground = scene.surfaces.front();
    CHECK(glm::cross(ground.edgeU, ground.edgeV).y > 0.0);
    CHECK(ground.origin.y == 0.0);
    for (int c = 0; c < 3; ++c) CHECK((ground.reflectance[c] >= 0.02 && ground.reflectance[c] <= 0.9));
    CHECK(scene.objects[0].path.size() == 11);
    settings.width = 8;
    CHECK_THROWS_AS(compositingOutdoor(map, bunny(), settings), std::invalid_argument);
    CHECK_THROWS_AS(compositingOutdoor(constantEnvironment(16, 8, glm::vec3(0.0f)), bunny(), {}), std::invalid_argument);
}

TEST_CASE("photo calibration: our camera projects the board's inner corners where OpenCV's K [R | t] does") {
    const PhotoCalibration c = readPhotoCalibration(kPhotos + "chessboard_left05_camera.txt");
    CHECK(c.width == 640);
    CHECK(c.height == 480);
    CHECK(c.fx == doctest::Approx(535.915734));
    glm::ivec2 crop;
    double off = 0.0;
    const Camera camera = cameraOf(c, glm::dmat4(1.0), crop, off);
    CHECK(off < 0.71);
    const glm::dmat4 clip = clipFromWorldD(camera);
    for (int j = 0; j < 6; ++j) {
        for (int i = 0; i < 9; ++i) {
            const glm::dvec3 X(0.025 * i, 0.025 * j, 0.0);
            const glm::dvec3 x = c.R * X + c.t;
            // OpenCV's pixel centres are whole; ours are at + 0.5, in the cropped window.
            const glm::dvec2 opencv(c.fx * x.x / x.z + c.cx + 0.5 - crop.x, c.fy * x.y / x.z + c.cy + 0.5 - crop.y);
            const glm::dvec4 h = clip * glm::dvec4(X, 1.0);
            const glm::dvec2 ours((h.x / h.w + 1.0) * 0.5 * camera.width, (1.0 - h.y / h.w) * 0.5 * camera.height);
            INFO("corner " << i << ", " << j << ": OpenCV " << opencv.x << ", " << opencv.y << "; ours " << ours.x << ", " << ours.y);
            REQUIRE(glm::length(ours - opencv) <= off + 1e-3);
        }
    }
    const std::string good = "image_size 640 480\nK 500 0 320 0 500 240 0 0 1\nR 1 0 0 0 1 0 0 0 1\ntvec 0 0 1\n";
    CHECK_NOTHROW(readPhotoCalibration(scratchFile("good.txt", good)));
    CHECK_THROWS_AS(readPhotoCalibration(scratchFile("none.txt", "# nothing\n")), std::runtime_error);
    CHECK_THROWS_AS(readPhotoCalibration(kPhotos + "no-such-file.txt"), std::runtime_error);
    CHECK_THROWS_AS(readPhotoCalibration(scratchFile("skew.txt", "image_size 640 480\nK 500 3 320 0 500 240 0 0 1\nR 1 0 0 0 1 0 0 0 1\ntvec 0 0 1\n")),
                    std::runtime_error);
    CHECK_THROWS_AS(readPhotoCalibration(scratchFile("scaled.txt", "image_size 640 480\nK 500 0 320 0 500 240 0 0 1\nR 2 0 0 0 1 0 0 0 1\ntvec 0 0 1\n")),
                    std::runtime_error);
    CHECK_THROWS_AS(readPhotoCalibration(scratchFile("mirror.txt", "image_size 640 480\nK 500 0 320 0 500 240 0 0 1\nR -1 0 0 0 1 0 0 0 1\ntvec 0 0 1\n")),
                    std::runtime_error);
    CHECK_THROWS_AS(readPhotoCalibration(scratchFile("short.txt", "image_size 640 480\nK 500 0 320 0 500 240 0 0\nR 1 0 0 0 1 0 0 0 1\ntvec 0 0 1\n")),
                    std::runtime_error);
}

TEST_CASE("chessboard case: the white squares are the bright ones of the photograph, and its values come back through the response") {
    const Image8 photo = readImage8(kPhotos + "chessboard_left05_undistorted.png");
    CHECK(photo.width == 640);
    CHECK(photo.height == 480);
    const PhotoCalibration calibration = readPhotoCalibration(kPhotos + "chessboard_left05_camera.txt");
    const EnvironmentMap light = readEnvironmentMap(builtinDataDir() + "/environments/blender_interior.exr");
    const PhotoCase c = compositingChessboard(photo, calibration, light, bunny());
    // Where the model's squares land in the photograph, the white ones are bright: at least
    // 66 of the 70 centres (a corner square lies in the board's shade) against the median.
    const glm::dmat4 clip = clipFromWorldD(c.scene.camera);
    std::vector<double> greys;
    for (int s = 0; s < 70; ++s) {
        const PatchSurface& square = c.scene.surfaces[size_t(s)];
        const glm::dvec4 h = clip * glm::dvec4(square.origin + 0.5 * (square.edgeU + square.edgeV), 1.0);
        const int x = c.crop.x + int((h.x / h.w + 1.0) * 0.5 * c.scene.camera.width);
        const int y = c.crop.y + int((1.0 - h.y / h.w) * 0.5 * c.scene.camera.height);
        greys.push_back(photo.rgb[3 * (size_t(y) * 640 + size_t(x))]);
    }
    std::vector<double> sorted = greys;
    std::nth_element(sorted.begin(), sorted.begin() + 35, sorted.end());
    int agree = 0;
    for (int s = 0; s < 70; ++s) agree += (c.scene.surfaces[size_t(s)].reflectance.x > 0.5) == (greys[size_t(s)] > sorted[35]);
    CHECK(agree >= 66);
    // The photograph comes back whole through the response: T(background) is its grey.
    const size_t k = size_t(200) * size_t(c.scene.camera.width) + 300;
    const uint8_t grey = photo.rgb[3 * (size_t(200 + c.crop.y) * 640 + size_t(300 + c.crop.x))];
    CHECK(std::lround(c.scene.response(double(c.scene.background[k].y))) == grey);
    Image8 wrong = photo;
    wrong.width = 320;
    CHECK_THROWS_AS(compositingChessboard(wrong, calibration, light, bunny()), std::invalid_argument);
    CHECK_THROWS_AS(readImage8(kPhotos + "no-such-photo.png"), std::runtime_error);
    CHECK_THROWS_AS(readImage8(kPhotos + "chessboard_left05_camera.txt"), std::runtime_error);
}

TEST_CASE("built-in compositing cases: every listed name builds from the data folder, others are refused") {
    for (const std::string& name : builtinCompositingCaseNames()) {
        CAPTURE(name);
        const BuiltinCompositingCase c = builtinCompositingCase(name, 64, 40, builtinDataDir());
        REQUIRE(!c.scene.objects.empty());
        CHECK(c.scene.objects[0].mesh.positions.size() == bunny().positions.size());
        if (name == "chessboard") {
            // The photograph's window, not the size asked for; the fit is reported.
            CHECK(c.scene.camera.width != 64);
            CHECK(c.note.find("exposure fitted") != std::string::npos);
            CHECK(!c.scene.background.empty());
        } else {
            CHECK(c.scene.camera.width == 64);
            CHECK(c.scene.camera.height == 40);
            CHECK(c.note.empty());
        }
    }
    const BuiltinCompositingCase slid = builtinCompositingCase("room", 64, 40, builtinDataDir());
    const BuiltinCompositingCase lifted = builtinCompositingCase("room-lift", 64, 40, builtinDataDir());
    CHECK(slid.scene.objects[0].path != lifted.scene.objects[0].path);
    CHECK_THROWS_AS(builtinCompositingCase("rooms", 64, 40, builtinDataDir()), std::invalid_argument);
    // A data folder without the mesh: the reader's error names the file.
    CHECK_THROWS_WITH_AS(builtinCompositingCase("room", 64, 40, "/nonexistent"),
                         doctest::Contains("/nonexistent/meshes/bunny_low.obj"), std::exception);
}
