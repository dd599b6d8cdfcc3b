#include "differential/scene/compositing_file.h"

#include <filesystem>
#include <numbers>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>

#include "differential/scene/photo_calibration.h"
#include "raster/portable_math.h"
#include "scenes/json_fields.h"
#include "scenes/read_file.h"
#include "scenes/scene_file.h"
#include "scenes/scene_file_parts.h"

namespace shadowlab {
namespace {

constexpr Interval kPixels{16.0, 4096.0, false, false};
constexpr Interval kReflectance{0.0, 1.0, false, true};

Camera readCamera(const JsonObject& o) {
    o.allowOnly({"eye", "target", "up", "fovy", "width", "height"});
    Camera camera;
    camera.eye = o["eye"].vec3(kCoordinate), camera.target = o["target"].vec3(kCoordinate);
    if (auto up = o.optional("up")) camera.up = up->vec3();
    camera.fovyDeg = o["fovy"].number({0.0, 180.0, true, true});
    camera.width = o["width"].integer(kPixels), camera.height = o["height"].integer(kPixels);
    camera.zNear = 0.01f, camera.zFar = 1000.0f;
    checkViewFrame(o, camera);
    return camera;
}

// {"file": calibration, "world_from_target": 16 numbers, row by row (default: identity)}.
Camera readCalibratedCamera(const JsonObject& o, const std::string& directory, glm::ivec2& crop) {
    o.allowOnly({"file", "world_from_target"});
    glm::dmat4 worldFromTarget(1.0);
    if (auto m = o.optional("world_from_target")) {
        const std::vector<JsonField> values = m->elements(16);
        for (int row = 0; row < 4; ++row) {
            for (int col = 0; col < 4; ++col) worldFromTarget[col][row] = values[size_t(4 * row + col)].number();
        }
        if (!isRigid(worldFromTarget)) {
            m->fail("must be rigid: a rotation (orthonormal, determinant +1, to 1e-4) and a translation, "
                    "its last row 0 0 0 1");
        }
    }
    Camera camera;
    try {
        const PhotoCalibration calibration =
            readPhotoCalibration((std::filesystem::path(directory) / o["file"].string()).string());
        double off = 0.0;
        camera = cameraOf(calibration, worldFromTarget, crop, off);
    } catch (const std::exception& error) {
        o["file"].fail(error.what());
    }
    checkViewFrame(o, camera);
    return camera;
}

PatchSurface readSurface(const JsonField& field) {
    const JsonObject o = field.object({"name", "origin", "edge_u", "edge_v", "cells", "reflectance", "emitted"});
    PatchSurface s;
    if (auto name = o.optional("name")) s.name = name->string();
    s.origin = glm::dvec3(o["origin"].vec3(kCoordinate)), s.edgeU = glm::dvec3(o["edge_u"].vec3(kCoordinate)),
        s.edgeV = glm::dvec3(o["edge_v"].vec3(kCoordinate));
    const std::vector<JsonField> cells = o["cells"].elements(2);
    s.cellsU = cells[0].integer({1.0, 4096.0, false, false}), s.cellsV = cells[1].integer({1.0, 4096.0, false, false});
    if (auto rho = o.optional("reflectance")) s.reflectance = glm::dvec3(rho->vec3(kReflectance));
    if (auto emitted = o.optional("emitted")) s.emitted = {glm::dvec3(emitted->vec3(kNonNegative))};
    return s;
}

// Each frame: {"translate": [x, y, z], "scale": s, "rotate_y": degrees}, applied as scale,
// then the turn about +Y, then the translation.
glm::mat4 readPlacement(const JsonField& field) {
    const JsonObject o = field.object({"translate", "scale", "rotate_y"});
    const glm::vec3 translate = o.has("translate") ? o["translate"].vec3(kCoordinate) : glm::vec3(0.0f);
    const float scale = o.has("scale") ? o["scale"].number(kPositive) : 1.0f;
    const float turn = o.has("rotate_y") ? o["rotate_y"].number({-3600.0, 3600.0, false, false}) : 0.0f;
    // The turn's sine and cosine from raster/portable_math.h (the same bits on every CPU).
    const double radians = double(turn) * std::numbers::pi / 180.0;
    const float c = float(portable::cos(radians)), s = float(portable::sin(radians));
    glm::mat4 rotation(1.0f);
    rotation[0][0] = c, rotation[0][2] = -s, rotation[2][0] = s, rotation[2][2] = c;
    return glm::translate(glm::mat4(1.0f), translate) * rotation * glm::scale(glm::mat4(1.0f), glm::vec3(scale));
}

SyntheticObject readObject(const JsonObject& o, const std::string& directory) {
    o.allowOnly({"mesh", "albedo", "path"});
    SyntheticObject object;
    object.mesh = readMesh(o["mesh"].object(), directory);
    if (auto albedo = o.optional("albedo")) object.albedo = glm::dvec3(albedo->vec3(kReflectance));
    for (const JsonField& frame : o["path"].elements()) object.path.push_back(readPlacement(frame));
    if (object.path.empty()) o["path"].fail("needs at least one frame");
    return object;
}

DomeRequest readDome(const JsonObject& o, const std::string& directory) {
    o.allowOnly({"map", "columns", "rows", "radius", "rotation", "grey"});
    DomeRequest dome;
    dome.map = (std::filesystem::path(directory) / o["map"].string()).string();
    if (auto c = o.optional("columns")) dome.columns = c->integer({4.0, 1024.0, false, false});
    if (auto r = o.optional("rows")) dome.rows = r->integer({1.0, 512.0, false, false});
    if (auto r = o.optional("radius")) dome.radiusM = r->number(kPositive);
    if (auto r = o.optional("rotation")) dome.rotationDeg = r->number({-3600.0, 3600.0, false, false});
    if (auto g = o.optional("grey")) dome.grey = g->boolean();
    return dome;
}

}  // namespace

CompositingFile loadCompositingFile(const std::string& path) { return parseCompositingFile(readWholeFile(path), path); }

CompositingFile parseCompositingFile(const std::string& text, const std::string& path) {
    const std::string directory = std::filesystem::path(path).parent_path().string();
    const nlohmann::json document = parseJson(text, path);
    const JsonObject o = JsonField(document, path, "").object(
        {"name", "photograph", "response", "camera", "calibration", "surfaces", "objects", "dome"});
    CompositingFile file;
    CompositingScene& scene = file.scene;
    scene.name = o.has("name") ? o["name"].string() : std::filesystem::path(path).stem().string();
    file.photograph = (std::filesystem::path(directory) / o["photograph"].string()).string();
    if (auto response = o.optional("response")) {
        const JsonObject r = response->object({"exposure", "gamma"});
        scene.response = {r["exposure"].number(kPositive), r["gamma"].number(kPositive)};
    }
    if (o.has("camera") == o.has("calibration")) o.field().fail("needs exactly one of \"camera\" and \"calibration\"");
    scene.camera = o.has("camera") ? readCamera(o["camera"].object())
                                   : readCalibratedCamera(o["calibration"].object(), directory, file.crop);
    for (const JsonField& surface : o["surfaces"].elements()) scene.surfaces.push_back(readSurface(surface));
    try {
        flattenPatches(scene.surfaces);   // its checks, reported against the file
    } catch (const std::invalid_argument& error) {
        o["surfaces"].fail(error.what());
    }
    for (const JsonField& object : o["objects"].elements()) {
        scene.objects.push_back(readObject(object.object(), directory));
        if (scene.objects.back().path.size() != scene.objects.front().path.size()) {
            object.fail("needs as many frames in its path as the first object");
        }
    }
    if (scene.objects.empty()) o["objects"].fail("needs at least one object");
    if (auto dome = o.optional("dome")) {
        file.dome = readDome(dome->object(), directory);
        // Counted before the map is read and the dome's patches are made.
        size_t patches = size_t(file.dome->columns) * size_t(file.dome->rows);
        for (const PatchSurface& s : scene.surfaces) patches += size_t(s.cellsU) * size_t(s.cellsV);
        if (patches > kMaxCompositingPatches)
            dome->fail("makes " + std::to_string(patches) + " patches with the surfaces, more than " +
                       std::to_string(kMaxCompositingPatches));
    }
    return file;
}

}  // namespace shadowlab
