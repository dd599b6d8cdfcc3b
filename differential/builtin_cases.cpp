#include "differential/builtin_cases.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "differential/outdoor_case.h"
#include "differential/photo_case.h"
#include "differential/scene/compositing_cases.h"
#include "scenes/obj_reader.h"
#include "shading/environment/environment_file.h"

namespace shadowlab {

const std::vector<std::string>& builtinCompositingCaseNames() {
    static const std::vector<std::string> names = {"room", "room-lift", "outdoor", "chessboard"};
    return names;
}

namespace {

// What the chessboard's fit found: the window of the photograph and the exposure.
std::string chessboardNote(const PhotoCase& c) {
    char text[256];
    std::snprintf(text, sizeof text,
                  "chessboard: the photograph's window %d x %d from (%d, %d), principal point %.2f px off its "
                  "centre; the response's exposure fitted to the white squares: %.6g",
                  c.scene.camera.width, c.scene.camera.height, c.crop.x, c.crop.y, c.offAxisPixels,
                  c.scene.response.exposure);
    return text;
}

}  // namespace

BuiltinCompositingCase builtinCompositingCase(const std::string& name, int width, int height,
                                              const std::string& dataDir) {
    if (std::ranges::find(builtinCompositingCaseNames(), name) == builtinCompositingCaseNames().end())
        throw std::invalid_argument("unknown built-in compositing case '" + name + "'");
    const Mesh bunny = readObj(dataDir + "/meshes/bunny_low.obj");
    if (name == "room") return {compositingRoom(bunny, RoomPath::UnderDesk, width, height), ""};
    if (name == "room-lift") return {compositingRoom(bunny, RoomPath::Lift, width, height), ""};
    if (name == "outdoor") {
        const OutdoorSettings settings{.width = width, .height = height};
        return {compositingOutdoor(readEnvironmentMap(dataDir + "/environments/blender_forest.exr"), bunny, settings),
                ""};
    }
    if (name == "chessboard") {
        const std::string photos = dataDir + "/photos/";
        const PhotoCase c = compositingChessboard(readImage8(photos + "chessboard_left05_undistorted.png"),
                                                  readPhotoCalibration(photos + "chessboard_left05_camera.txt"),
                                                  readEnvironmentMap(dataDir + "/environments/blender_interior.exr"),
                                                  bunny);
        return {c.scene, chessboardNote(c)};
    }
    throw std::logic_error("builtinCompositingCase: '" + name + "' is listed but not built");
}

}  // namespace shadowlab
