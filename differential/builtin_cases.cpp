#include "differential/builtin_cases.h"

#include <algorithm>
#include <cstdio>
#include <iterator>
#include <stdexcept>

#include "differential/outdoor_case.h"
#include "differential/photo_case.h"
#include "differential/scene/compositing_cases.h"
#include "scenes/obj_reader.h"
#include "shading/environment/environment_file.h"

namespace shadowlab {

namespace {

// What every case is made from: the object, the image size asked for, the data folder.
struct CaseRequest {
    const Mesh& object;
    int width, height;
    const std::string& dataDir;
};

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

BuiltinCompositingCase chessboard(const CaseRequest& r) {
    const std::string photos = r.dataDir + "/photos/";
    const PhotoCase c = compositingChessboard(readImage8(photos + "chessboard_left05_undistorted.png"),
                                              readPhotoCalibration(photos + "chessboard_left05_camera.txt"),
                                              readEnvironmentMap(r.dataDir + "/environments/blender_interior.exr"),
                                              r.object);
    return {c.scene, chessboardNote(c)};
}

struct CaseEntry {
    const char* name;
    BuiltinCompositingCase (*build)(const CaseRequest&);
};

// The one list of the cases, in the order the command's help gives them.
constexpr CaseEntry kCases[] = {
    {"room", [](const CaseRequest& r) -> BuiltinCompositingCase {
         return {compositingRoom(r.object, RoomPath::UnderDesk, r.width, r.height), ""};
     }},
    {"room-lift", [](const CaseRequest& r) -> BuiltinCompositingCase {
         return {compositingRoom(r.object, RoomPath::Lift, r.width, r.height), ""};
     }},
    {"outdoor", [](const CaseRequest& r) -> BuiltinCompositingCase {
         const EnvironmentMap map = readEnvironmentMap(r.dataDir + "/environments/blender_forest.exr");
         return {compositingOutdoor(map, r.object, {.width = r.width, .height = r.height}), ""};
     }},
    {"chessboard", chessboard},
};

}  // namespace

const std::vector<std::string>& builtinCompositingCaseNames() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> list;
        for (const CaseEntry& entry : kCases) list.push_back(entry.name);
        return list;
    }();
    return names;
}

BuiltinCompositingCase builtinCompositingCase(const std::string& name, int width, int height,
                                              const std::string& dataDir) {
    const auto entry = std::ranges::find_if(kCases, [&](const CaseEntry& e) { return name == e.name; });
    if (entry == std::end(kCases)) throw std::invalid_argument("unknown built-in compositing case '" + name + "'");
    const Mesh bunny = readObj(dataDir + "/meshes/bunny_low.obj");
    return entry->build({bunny, width, height, dataDir});
}

}  // namespace shadowlab
