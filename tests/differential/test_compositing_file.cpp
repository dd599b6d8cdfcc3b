// Compositing scene files (differential/scene/compositing_file.h, differential/
// compositing_inputs.h; docs/scene-format.md, "Compositing scenes"): the shipped chessboard
// file reads as its calibration, photograph, board, dome and path say, and composites; a
// malformed file is refused with the file and field named.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "differential/composite.h"
#include "differential/compositing_inputs.h"
#include "differential/scene/compositing_file.h"
#include "scenes/scene_file.h"
#include "shading/image_io.h"

using namespace shadowlab;

namespace {

const std::string kFile = builtinSceneDir() + "/compositing/chessboard.json";

std::filesystem::path scratch() {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "shadowlab-compositing-file";
    std::filesystem::create_directories(dir);
    return dir;
}

// The shipped file's calibration, replaced by a camera in some variants.
constexpr const char* kCalibrationBlock =
    "\"calibration\": {\n"
    "    \"file\": \"../../photos/chessboard_left05_camera.txt\",\n"
    "    \"world_from_target\": [1, 0, 0, 0,\n"
    "                          0, 0, -1, 0,\n"
    "                          0, 1, 0, 0,\n"
    "                          0, 0, 0, 1]\n"
    "  }";

// The shipped file with one text replaced, in a scratch folder, its "../../" paths made to
// point at the data folder.
std::string variant(const std::string& name, const std::string& from, const std::string& to) {
    std::ifstream in(kFile);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const size_t at = text.find(from);
    REQUIRE(at != std::string::npos);
    text.replace(at, from.size(), to);
    for (size_t up = text.find("\"../../"); up != std::string::npos; up = text.find("\"../../", up)) {
        text.replace(up + 1, 6, builtinDataDir() + "/");
    }
    const std::filesystem::path path = scratch() / (name + ".json");
    std::ofstream(path) << text;
    return path.string();
}

std::string errorOf(const std::string& path) {
    try {
        readCompositingInputs(loadCompositingFile(path));
    } catch (const std::exception& error) {
        std::filesystem::remove(path);
        return error.what();
    }
    std::filesystem::remove(path);
    return "";
}

}  // namespace

TEST_CASE("compositing file: the shipped chessboard reads as it says and composites") {
    const CompositingFile file = loadCompositingFile(kFile);
    CHECK(file.scene.name == "chessboard-file");
    CHECK(file.scene.camera.width == 592);
    CHECK(file.scene.camera.height == 470);
    CHECK(file.crop == glm::ivec2(47, 1));
    REQUIRE(file.scene.surfaces.size() == 1);
    CHECK(file.scene.surfaces[0].cellsU == 10);
    REQUIRE(file.scene.objects.size() == 2);
    CHECK(file.scene.objects[0].path.size() == 3);
    CHECK(file.scene.objects[1].path.size() == 3);
    // Frame 1: scaled by 0.005, turned 45 degrees about +Y, then moved.
    const glm::vec4 tip = file.scene.objects[0].path[1] * glm::vec4(1, 0, 0, 1);
    CHECK(tip.x == doctest::Approx(0.10 + 0.005 * 0.70710678).epsilon(1e-5));
    CHECK(tip.z == doctest::Approx(0.06 - 0.005 * 0.70710678).epsilon(1e-5));
    REQUIRE(file.dome.has_value());
    const CompositingScene scene = readCompositingInputs(file);
    CHECK(scene.background.size() == size_t(592 * 470));
    CHECK(scene.surfaces.size() == 1 + 32 * 8);
    const DifferentialModel model = preprocess(scene);
    const PreparedObject object = prepareObject(model, scene.objects);
    CompositeSettings settings;
    settings.ldr = true;
    const CompositeFrame frame = compositeFrame(model, object, placementsAt(scene.objects, 1), settings);
    size_t objectPixels = 0;
    for (uint8_t p : frame.objectPixels) objectPixels += p;
    CHECK(objectPixels > 500);
    CHECK(!frame.clusters.empty());
}

TEST_CASE("compositing file: malformed files are refused, naming the file and the field") {
    CHECK(errorOf(variant("key", "\"surfaces\"", "\"surfacez\"")).find("surfacez") != std::string::npos);
    CHECK(errorOf(variant("both", "\"calibration\": {", "\"camera\": {\"eye\": [0, 1, 1], \"target\": [0, 0, 0], \"fovy\": 40, "
                                                        "\"width\": 64, \"height\": 64}, \"calibration\": {"))
              .find("exactly one of") != std::string::npos);
    CHECK(errorOf(variant("photo", "chessboard_left05_undistorted.png", "no-such-photo.png")).find("no-such-photo.png") !=
          std::string::npos);
    CHECK(errorOf(variant("cells", "\"cells\": [10, 7]", "\"cells\": [0, 7]")).find("cells") != std::string::npos);
    CHECK(errorOf(variant("rho", "[0.43, 0.43, 0.43]", "[1.5, 0.43, 0.43]")).find("reflectance") != std::string::npos);
    CHECK(errorOf(variant("flat", "\"edge_v\": [0, 0, -0.175]", "\"edge_v\": [0.5, 0, 0]")).find("no area") != std::string::npos);
    CHECK(errorOf(variant("path", "\"path\": [", "\"path\": [], \"unused\": [")).find("unused") != std::string::npos);
    CHECK(errorOf(variant("frames", "{\"translate\": [0.18, 0.012, 0.11]},\n        {\"translate\": [0.18, 0.012, 0.11]},", ""))
              .find("as many frames") != std::string::npos);
    CHECK(errorOf(variant("scale", "\"scale\": 0.005}", "\"scale\": -1}")).find("scale") != std::string::npos);
    CHECK(errorOf(variant("calibration", "chessboard_left05_camera.txt", "missing_camera.txt")).find("missing_camera.txt") !=
          std::string::npos);
    // Every camera is checked as a scene file's is (viewFrameProblem), and a calibration's
    // placement must be rigid: each of these exited 0 and returned the photograph unchanged.
    const std::string calibration = kCalibrationBlock;
    const std::string camera = "\"camera\": {\"eye\": [0, 1, 1], \"fovy\": 40, \"width\": 64, \"height\": 64, ";
    CHECK(errorOf(variant("eye", calibration, camera + "\"target\": [0, 1, 1]}"))
              .find("camera.target: the camera's eye and target must differ") != std::string::npos);
    CHECK(errorOf(variant("up", calibration, camera + "\"target\": [0, 3, 1]}"))
              .find("camera: up must not be zero or parallel") != std::string::npos);
    const std::string rigid = "calibration.world_from_target: must be rigid";
    const std::string identityRows = "[1, 0, 0, 0,\n                          0, 0, -1, 0,\n                          0, 1, 0, 0,";
    CHECK(errorOf(variant("singular", identityRows, "[1, 0, 0, 0,  0, 0, 0, 0,  0, 1, 0, 0,")).find(rigid) != std::string::npos);
    CHECK(errorOf(variant("scaled", identityRows, "[2, 0, 0, 0,  0, 0, -2, 0,  0, 2, 0, 0,")).find(rigid) != std::string::npos);
    CHECK(errorOf(variant("mirror", identityRows, "[-1, 0, 0, 0,  0, 0, -1, 0,  0, 1, 0, 0,")).find(rigid) != std::string::npos);
    CHECK(errorOf(variant("projective", "0, 0, 0, 1]", "0, 0, 0.5, 1]")).find(rigid) != std::string::npos);
    // A dome past the patch budget, refused at reading (it was built whole, then refused).
    CHECK(errorOf(variant("dome", "\"columns\": 32, \"rows\": 8", "\"columns\": 1024, \"rows\": 512"))
              .find("dome: makes 524358 patches with the surfaces, more than 65536") != std::string::npos);
    // A photograph smaller than the calibrated camera's window.
    const std::filesystem::path small = scratch() / "small.png";
    writePng(small, 32, 32, std::vector<uint8_t>(32 * 32 * 3, 128));
    std::string quoted = "\"";   // appended, not chained: GCC 12 warns wrongly of a chain of string +
    quoted += small.string();
    quoted += "\"";
    CHECK(errorOf(variant("window", "\"../../photos/chessboard_left05_undistorted.png\"", quoted)).find("window") != std::string::npos);
    std::filesystem::remove(small);
}
