// Every kind of mistake in a scene file is a SceneError whose message names the file
// and the field path. Each case breaks one thing in a scene that otherwise loads.
#include <cstring>
#include <filesystem>
#include <functional>

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>
#include <stb_image_write.h>

#include "scenes/albedo_texture.h"
#include "scenes/scene_file.h"
#include "scenes/scene_file_parts.h"
#include "scenes/scene_limits.h"
#include "tests/scenes/scene_test_files.h"

using namespace shadowlab;
using nlohmann::json;

namespace {

// Uses every mesh kind, material model and light type once.
json validScene() {
    return json::parse(R"({
      "description": "test scene",
      "meshes": [
        {"name": "ground", "procedural": "grid", "size": [20, 20], "divisions": [4, 4]},
        {"name": "tri", "file": "tri.obj"},
        {"name": "ball", "procedural": "uv-sphere", "radius": 1, "slices": 8, "stacks": 4},
        {"name": "box", "procedural": "box", "min": [0, 0, 0], "max": [1, 1, 1]}
      ],
      "materials": [
        {"name": "white", "model": "lambert", "albedo": [0.8, 0.8, 0.8]},
        {"name": "shiny", "model": "blinn-phong", "specular": [0.2, 0.2, 0.2], "shininess": 20}
      ],
      "instances": [
        {"mesh": "ground", "material": "white"},
        {"mesh": "tri", "material": "shiny", "translate": [0, 1, 0]}
      ],
      "lights": [
        {"type": "disk", "position": [4, 8, 3], "normal": [-4, -8, -3], "radius": 0.5, "power": 400},
        {"type": "point", "position": [0, 5, 0], "power": 10},
        {"type": "spot", "position": [0, 5, 0], "direction": [0, -1, 0], "coneAngle": 30, "power": 10},
        {"type": "directional", "direction": [1, 1, 0], "color": [1, 0.9, 0.8], "power": 2},
        {"type": "rectangle", "position": [0, 5, 0], "halfEdgeU": [1, 0, 0], "halfEdgeV": [0, 0, 0.5], "power": 10}
      ],
      "camera": {"eye": [0, 4, 9], "target": [0, 0.5, 0], "fovy": 45, "width": 64, "height": 40},
      "environment": {"ambient": [0.02, 0.02, 0.02]}
    })");
}

// leaf.png: 4 x 2 texels with alpha, the left half 0 and the right half 255; grey.png: no alpha.
void writeAlphaTextures(const test::TempDir& dir) {
    std::vector<unsigned char> rgba(4 * 2 * 4, 200);
    for (int k = 0; k < 8; ++k) rgba[4 * size_t(k) + 3] = (k % 4) < 2 ? 0 : 255;
    REQUIRE(stbi_write_png(dir.path("leaf.png").c_str(), 4, 2, 4, rgba.data(), 4 * 4) != 0);
    const std::vector<unsigned char> grey(8, 128);
    REQUIRE(stbi_write_png(dir.path("grey.png").c_str(), 4, 2, 1, grey.data(), 4) != 0);
}

// Mesh files the cases point meshes[1] at, and the alpha textures materials may name.
void writeMeshFiles(const test::TempDir& dir) {
    const std::string corners = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    dir.write("tri.obj", corners + "f 1 2 3\n");
    dir.write("bad-index.obj", corners + "f 1 2 4\n");
    dir.write("nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n");
    dir.write("no-faces.obj", corners);
    dir.write("notes.txt", corners);
    const std::string plyHeader = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
                                  "property float y\nproperty float z\nelement face 1\n"
                                  "property list uchar int vertex_indices\nend_header\n";
    dir.write("truncated.ply", plyHeader + std::string(20, '\0'));
    dir.write("bad-index.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                               "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                               "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n");
    std::filesystem::create_directory(dir.path("folder.obj"));
    writeAlphaTextures(dir);
}

struct Case {
    std::string what;
    std::function<void(json&)> change;
    std::vector<std::string> pieces;   // besides the file name, which every message must contain
};

// JSON cannot spell infinity; the markers "@HUGE@" and "-@HUGE@" become 1e999 and
// -1e999 in the file text, numbers too large for a double.
std::string render(const json& scene) {
    std::string text = scene.dump(2);
    for (const auto& [marker, number] : {std::pair{"\"-@HUGE@\"", "-1e999"}, std::pair{"\"@HUGE@\"", "1e999"}})
        for (size_t at; (at = text.find(marker)) != std::string::npos;) text.replace(at, std::strlen(marker), number);
    return text;
}

void checkCases(const std::vector<Case>& cases) {
    const test::TempDir dir;
    writeMeshFiles(dir);
    for (const Case& c : cases) {
        CAPTURE(c.what);
        json scene = validScene();
        c.change(scene);
        const std::string path = dir.write("scene.json", render(scene));
        std::vector<std::string> pieces = c.pieces;
        pieces.push_back(path + ": ");
        test::checkMessage(test::sceneErrorOf([&] { loadScene(path); }), pieces);
    }
}

}  // namespace

TEST_CASE("the unbroken test scene loads") {
    const test::TempDir dir;
    writeMeshFiles(dir);
    const Scene scene = loadScene(dir.write("scene.json", render(validScene())));
    CHECK(scene.meshes.size() == 4);
    CHECK(scene.lights.size() == 5);
    CHECK(scene.lights[3].direction == glm::normalize(glm::vec3(1.0f, 1.0f, 0.0f)));
    CHECK(scene.lights[3].intensity == glm::vec3(2.0f, 1.8f, 1.6f));
    CHECK(scene.lights[4].halfEdgeV == glm::vec3(0.0f, 0.0f, 0.5f));
    CHECK(scene.materials[1].model == MaterialModel::BlinnPhong);
    CHECK(scene.materials[1].albedo == Material{}.albedo);   // default kept
}

// A sun's size (conventions.md, "Lights"): absent, the point-like sun every scene had.
TEST_CASE("a sun's angular diameter loads, and without it the sun is point-like") {
    const test::TempDir dir;
    writeMeshFiles(dir);
    json s = validScene();
    CHECK(loadScene(dir.write("plain.json", render(s))).lights[3].angularDiameterDeg == 0.0f);
    s["lights"][3]["angularDiameter"] = 2.5;
    const Scene sized = loadScene(dir.write("sized.json", render(s)));
    CHECK(sized.lights[3].angularDiameterDeg == 2.5f);
    CHECK(sized.lights[3].direction == loadScene(dir.path("plain.json")).lights[3].direction);
}

// KHR_lights_punctual's range and inner cone, which a glTF file's lights carry, are a scene
// file's too (a glTF model placed by "models" brings no lights of its own).
TEST_CASE("a point's and a spot's range and a spot's inner cone load, and without them the light is unbounded and its cone hard") {
    const test::TempDir dir;
    writeMeshFiles(dir);
    json s = validScene();
    const Scene plain = loadScene(dir.write("plain.json", render(s)));
    CHECK(plain.lights[1].range == 0.0f);
    CHECK(!plain.lights[2].innerConeAngleDeg);
    s["lights"][1]["range"] = 4;
    s["lights"][2]["range"] = 6.5;
    s["lights"][2]["innerConeAngle"] = 20;
    const Scene falloff = loadScene(dir.write("falloff.json", render(s)));
    CHECK(falloff.lights[1].range == 4.0f);
    CHECK(falloff.lights[2].range == 6.5f);
    REQUIRE(falloff.lights[2].innerConeAngleDeg);
    CHECK(*falloff.lights[2].innerConeAngleDeg == 20.0f);
}

TEST_CASE("phong and ggx materials load with their own terms") {
    const test::TempDir dir;
    writeMeshFiles(dir);
    json s = validScene();
    s["materials"].push_back({{"name", "glossy"}, {"model", "phong"}, {"specular", {0.5, 0.5, 0.5}}, {"shininess", 500}});
    s["materials"].push_back({{"name", "metal"}, {"model", "ggx"}, {"specular", {0.9, 0.6, 0.3}}, {"roughness", 0.25}});
    const Scene scene = loadScene(dir.write("scene.json", render(s)));
    REQUIRE(scene.materials.size() == 4);
    CHECK(scene.materials[2].model == MaterialModel::Phong);
    CHECK(scene.materials[2].shininess == 500.0f);
    CHECK(scene.materials[3].model == MaterialModel::Ggx);
    CHECK(scene.materials[3].roughness == 0.25f);
    CHECK(scene.materials[3].specular == glm::vec3(0.9f, 0.6f, 0.3f));
}

TEST_CASE("missing fields and wrong types") {
    checkCases({
        {"no camera", [](json& s) { s.erase("camera"); }, {"missing required field \"camera\""}},
        {"no eye", [](json& s) { s["camera"].erase("eye"); }, {"camera: missing required field \"eye\""}},
        {"no power", [](json& s) { s["lights"][1].erase("power"); }, {"lights[1]: missing required field \"power\""}},
        {"no grid size", [](json& s) { s["meshes"][0].erase("size"); }, {"meshes[0]: missing required field \"size\""}},
        {"string for number", [](json& s) { s["camera"]["fovy"] = "45"; }, {"camera.fovy: must be a number, got \"45\""}},
        {"fraction for integer", [](json& s) { s["meshes"][0]["divisions"][0] = 4.5; },
         {"meshes[0].divisions[0]: must be an integer, got 4.5"}},
        {"two numbers for a point", [](json& s) { s["camera"]["eye"] = {0, 4}; },
         {"camera.eye: must be an array of 3 numbers, got [0,4]"}},
        {"object for array", [](json& s) { s["lights"] = json::object(); }, {"lights: must be an array, got {}"}},
        {"number for name", [](json& s) { s["instances"][0]["mesh"] = 3; }, {"instances[0].mesh: must be a string, got 3"}},
        {"string for bool", [](json& s) { s["instances"][1]["fit"] = {{"ground", "yes"}}; },
         {"instances[1].fit.ground: must be true or false"}},
        {"number for description", [](json& s) { s["description"] = 1; }, {"description: must be a string"}},
        {"mesh with file and procedural", [](json& s) { s["meshes"][1]["procedural"] = "box"; },
         {"meshes[1]: needs exactly one of \"file\" and \"procedural\""}},
    });
}

TEST_CASE("non-finite numbers, unknown names, unknown keys") {
    checkCases({
        {"infinite near", [](json& s) { s["camera"]["near"] = "@HUGE@"; },
         {"camera.near: invalid JSON: ", "number overflow parsing '1e999'"}},
        {"minus infinity in an array", [](json& s) { s["lights"][1]["position"][2] = "-@HUGE@"; },
         {"lights[1].position[2]: invalid JSON: ", "'-1e999'"}},
        {"beyond float", [](json& s) { s["materials"][0]["albedo"][1] = 1e39; },
         {"materials[0].albedo[1]: must be a finite number within float range"}},
        {"light type", [](json& s) { s["lights"][0]["type"] = "area"; },
         {"lights[0].type: unknown value \"area\" (allowed: point, spot, directional, disk, rectangle)"}},
        {"material model", [](json& s) { s["materials"][0]["model"] = "cook-torrance"; },
         {"materials[0].model: unknown value \"cook-torrance\" (allowed: lambert, blinn-phong, phong, ggx)"}},
        {"procedural kind", [](json& s) { s["meshes"][0]["procedural"] = "plane"; },
         {"meshes[0].procedural: unknown value \"plane\""}},
        {"typo in light", [](json& s) { s["lights"][0]["radus"] = 0.5; },
         {"lights[0]: unknown key \"radus\" (allowed: type, position, normal, radius, color, power)"}},
        {"typo at top", [](json& s) { s["camra"] = s["camera"]; }, {"unknown key \"camra\""}},
        {"typo in camera", [](json& s) { s["camera"]["fov"] = 45; }, {"camera: unknown key \"fov\""}},
        {"typo in instance", [](json& s) { s["instances"][1]["transalte"] = {0, 1, 0}; },
         {"instances[1]: unknown key \"transalte\""}},
        {"specular on lambert", [](json& s) { s["materials"][0]["specular"] = {1, 1, 1}; },
         {"materials[0]: unknown key \"specular\""}},
        {"roughness on blinn-phong", [](json& s) { s["materials"][1]["roughness"] = 0.3; },
         {"materials[1]: unknown key \"roughness\""}},
        {"shininess on ggx", [](json& s) { s["materials"][1]["model"] = "ggx"; },
         {"materials[1]: unknown key \"shininess\""}},
        {"radius on grid", [](json& s) { s["meshes"][0]["radius"] = 1; }, {"meshes[0]: unknown key \"radius\""}},
        {"field of another light type", [](json& s) { s["lights"][1]["radius"] = 1; },
         {"lights[1]: unknown key \"radius\""}},
        {"unknown mesh", [](json& s) { s["instances"][0]["mesh"] = "grnd"; },
         {"instances[0].mesh: no mesh is named \"grnd\""}},
        {"unknown material", [](json& s) { s["instances"][0]["material"] = "red"; },
         {"instances[0].material: no material is named \"red\""}},
        {"duplicate mesh", [](json& s) { s["meshes"][1]["name"] = "ground"; },
         {"meshes[1].name: another mesh is already named \"ground\""}},
        {"duplicate material", [](json& s) { s["materials"][1]["name"] = "white"; },
         {"materials[1].name: another material is already named \"white\""}},
    });
}

TEST_CASE("degenerate lights") {
    checkCases({
        {"zero disk normal", [](json& s) { s["lights"][0]["normal"] = {0, 0, 0}; },
         {"lights[0].normal: must not be the zero vector"}},
        {"zero spot direction", [](json& s) { s["lights"][2]["direction"] = {0, 0, 0}; },
         {"lights[2].direction: must not be the zero vector"}},
        {"zero directional direction", [](json& s) { s["lights"][3]["direction"] = {0, 0, 0}; },
         {"lights[3].direction: must not be the zero vector"}},
        {"negative disk radius", [](json& s) { s["lights"][0]["radius"] = -1; },
         {"lights[0].radius: must be > 0, got -1"}},
        {"zero disk radius", [](json& s) { s["lights"][0]["radius"] = 0; }, {"lights[0].radius: must be > 0, got 0"}},
        {"parallel rectangle edges", [](json& s) { s["lights"][4]["halfEdgeV"] = {2, 0, 0}; },
         {"lights[4].halfEdgeV: the rectangle has zero area"}},
        {"zero rectangle edge", [](json& s) { s["lights"][4]["halfEdgeU"] = {0, 0, 0}; },
         {"lights[4].halfEdgeV: the rectangle has zero area"}},
        {"skewed rectangle", [](json& s) { s["lights"][4]["halfEdgeV"] = {1, 0, 1}; },
         {"lights[4].halfEdgeV: must be perpendicular to halfEdgeU"}},
        {"zero cone", [](json& s) { s["lights"][2]["coneAngle"] = 0; },
         {"lights[2].coneAngle: must be in (0, 90], got 0"}},
        {"cone beyond 90", [](json& s) { s["lights"][2]["coneAngle"] = 95; },
         {"lights[2].coneAngle: must be in (0, 90], got 95"}},
        {"zero range", [](json& s) { s["lights"][1]["range"] = 0; }, {"lights[1].range: must be > 0, got 0"}},
        {"inner cone at the cone", [](json& s) { s["lights"][2]["innerConeAngle"] = 30; },
         {"lights[2].innerConeAngle: must be in [0, 30), got 30"}},
        {"range of a sun", [](json& s) { s["lights"][3]["range"] = 4; }, {"lights[3]: unknown key \"range\""}},
        {"negative sun size", [](json& s) { s["lights"][3]["angularDiameter"] = -0.5; },
         {"lights[3].angularDiameter: must be in [0, 180), got -0.5"}},
        {"sun as wide as a hemisphere", [](json& s) { s["lights"][3]["angularDiameter"] = 180; },
         {"lights[3].angularDiameter: must be in [0, 180), got 180"}},
        {"sun size as text", [](json& s) { s["lights"][3]["angularDiameter"] = "2"; },
         {"lights[3].angularDiameter: must be a number"}},
        {"angular size of a point light", [](json& s) { s["lights"][1]["angularDiameter"] = 2; },
         {"lights[1]: unknown key \"angularDiameter\""}},
        {"angular size of a disk light", [](json& s) { s["lights"][0]["angularDiameter"] = 2; },
         {"lights[0]: unknown key \"angularDiameter\""}},
        {"negative power", [](json& s) { s["lights"][1]["power"] = -2; }, {"lights[1].power: must be >= 0, got -2"}},
        {"negative colour", [](json& s) { s["lights"][3]["color"][2] = -0.5; },
         {"lights[3].color[2]: must be >= 0, got -0.5"}},
        {"infinite intensity", [](json& s) { s["lights"][3]["color"] = {3e38, 1, 1}; },
         {"lights[3].power: color * power overflows float"}},
        {"no lights", [](json& s) { s["lights"] = json::array(); }, {"lights: needs at least one light, or an environment map (environment.map)"}},
    });
}

TEST_CASE("camera, sizes and transforms out of range") {
    checkCases({
        {"zero fovy", [](json& s) { s["camera"]["fovy"] = 0; }, {"camera.fovy: must be in (0, 180), got 0"}},
        {"negative fovy", [](json& s) { s["camera"]["fovy"] = -5; }, {"camera.fovy: must be in (0, 180), got -5"}},
        {"fovy 180", [](json& s) { s["camera"]["fovy"] = 180; }, {"camera.fovy: must be in (0, 180), got 180"}},
        {"zero width", [](json& s) { s["camera"]["width"] = 0; }, {"camera.width: must be in [1, 8192], got 0"}},
        {"near beyond far", [](json& s) { s["camera"]["near"] = 10; s["camera"]["far"] = 5; },
         {"camera.far: near must be less than far"}},
        {"near equal to far", [](json& s) { s["camera"]["near"] = 5; s["camera"]["far"] = 5; },
         {"camera.far: near must be less than far"}},
        {"near beyond default far", [](json& s) { s["camera"]["near"] = 200; },
         {"camera.near: near must be less than far"}},
        {"zero near", [](json& s) { s["camera"]["near"] = 0; }, {"camera.near: must be > 0, got 0"}},
        {"eye on target", [](json& s) { s["camera"]["target"] = s["camera"]["eye"]; },
         {"camera.target: the camera's eye and target must differ"}},
        {"looking straight down with up +Y", [](json& s) { s["camera"]["eye"] = {0, 9, 0}; s["camera"]["target"] = {0, 0, 0}; },
         {"camera: up must not be zero or parallel to the viewing direction"}},
        {"zero grid size", [](json& s) { s["meshes"][0]["size"][0] = 0; }, {"meshes[0].size[0]: must be > 0, got 0"}},
        {"negative sphere radius", [](json& s) { s["meshes"][2]["radius"] = -1; },
         {"meshes[2].radius: must be > 0, got -1"}},
        {"two slices", [](json& s) { s["meshes"][2]["slices"] = 2; }, {"meshes[2].slices: must be in [3, 16384], got 2"}},
        {"one stack", [](json& s) { s["meshes"][2]["stacks"] = 1; }, {"meshes[2].stacks: must be in [2, 16384], got 1"}},
        {"flat box", [](json& s) { s["meshes"][3]["max"] = {1, 0, 1}; }, {"meshes[3].max: must be greater than min"}},
        {"albedo above 1", [](json& s) { s["materials"][0]["albedo"][0] = 1.5; },
         {"materials[0].albedo[0]: must be in [0, 1], got 1.5"}},
        {"zero shininess", [](json& s) { s["materials"][1]["shininess"] = 0; },
         {"materials[1].shininess: must be > 0, got 0"}},
        {"zero roughness", [](json& s) { s["materials"][1] = {{"name", "rough"}, {"model", "ggx"}, {"roughness", 0}}; },
         {"materials[1].roughness: must be in (0, 1], got 0"}},
        {"negative scale", [](json& s) { s["instances"][1]["scale"] = -1; }, {"instances[1].scale: must be > 0, got -1"}},
        {"zero scale axis", [](json& s) { s["instances"][1]["scale"] = {1, 0, 1}; },
         {"instances[1].scale[1]: must be > 0, got 0"}},
        {"matrix and translate", [](json& s) { s["instances"][1]["matrix"] = json::array(); },
         {"instances[1].matrix: cannot be combined with translate, rotate or scale"}},
        {"projective matrix", [](json& s) { s["instances"][0]["matrix"] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 1, 1}; },
         {"instances[0].matrix: the last row must be 0 0 0 1"}},
        {"mirroring matrix", [](json& s) { s["instances"][0]["matrix"] = {-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}; },
         {"instances[0].matrix: the upper-left 3x3 must have a positive determinant"}},
        {"short matrix", [](json& s) { s["instances"][0]["matrix"] = {1, 0, 0}; },
         {"instances[0].matrix: must be an array of 16 numbers"}},
        {"zero repeat", [](json& s) { s["instances"][1]["repeat"] = {{"count", {0, 1, 1}}, {"offset", {1, 0, 0}}}; },
         {"instances[1].repeat.count[0]: must be in [1, 1024], got 0"}},
        {"fitting a flat mesh to a height", [](json& s) { s["instances"][0]["fit"] = {{"height", 2}}; },
         {"instances[0].fit.height: the mesh has no extent in y to scale"}},
    });
}

// Each of these asked for gigabytes before it was refused: the limits (scene_limits.h) are
// checked before the meshes or instances are made.
TEST_CASE("scene limits: counted before anything is allocated") {
    checkCases({
        {"a repeat of 1024^3 copies", [](json& s) { s["instances"][1]["repeat"] = {{"count", {1024, 1024, 1024}}, {"offset", {1, 1, 1}}}; },
         {"instances[1].repeat.count: makes 1073741824 copies; a scene holds at most 65536 instances"}},
        {"a repeat past the instance limit with the instances before it", [](json& s) {
             s["instances"][1]["repeat"] = {{"count", {256, 256, 1}}, {"offset", {1, 1, 1}}};
         }, {"instances[1].repeat.count: makes 65536 copies; a scene holds at most 65536 instances"}},
        {"a 16384 x 16384 grid", [](json& s) { s["meshes"][0]["divisions"] = {16384, 16384}; },
         {"meshes[0].divisions: makes 536870912 triangles, more than a scene may hold (33554432)"}},
        {"a 16384 x 16384 sphere", [](json& s) { s["meshes"][2]["slices"] = 16384; s["meshes"][2]["stacks"] = 16384; },
         {"meshes[2].stacks: makes 536838144 triangles, more than a scene may hold (33554432)"}},
        {"a translation beyond the world's bound", [](json& s) { s["instances"][1]["translate"] = {3e38, 0, 0}; },
         {"instances[1].translate[0]: must be in [-1e+06, 1e+06], got 3e+38"}},
        {"a transform placing a vertex beyond the world's bound", [](json& s) {
             s["instances"][1]["translate"] = {9e5, 0, 0}; s["instances"][1]["scale"] = 2e38;
         },
         {"instances[1]: instance \"tri\": vertex 1 lands outside the world (every coordinate in [-1e+06, 1e+06] metres)"}},
        {"a repeat whose copies leave the world", [](json& s) {
             s["instances"][1]["translate"] = {9e5, 0, 0};
             s["instances"][1]["repeat"] = {{"count", {3, 1, 1}}, {"offset", {2e5, 0, 0}}};
         }, {"instances[1]: instance \"tri[1]\": vertex 0 lands outside the world"}},
        {"instances past the triangle limit", [](json& s) {
             s["meshes"][0]["divisions"] = {2048, 2048};   // 8.4 M triangles, five copies
             s["instances"][0]["repeat"] = {{"count", {5, 1, 1}}, {"offset", {1, 0, 0}}};
         }, {"the scene has 41943041 world-space triangles, more than the limit of 33554432"}},
    });
}

TEST_CASE("mesh files: missing, unreadable, malformed, empty scenes") {
    auto meshFile = [](const char* file) { return [file](json& s) { s["meshes"][1]["file"] = file; }; };
    checkCases({
        {"missing OBJ", meshFile("missing.obj"), {"meshes[1].file: ", "missing.obj: cannot open"}},
        {"missing PLY", meshFile("missing.ply"), {"meshes[1].file: ", "missing.ply: cannot open"}},
        {"directory", meshFile("folder.obj"), {"meshes[1].file: ", "folder.obj: is a directory"}},
        {"unknown format", meshFile("notes.txt"), {"meshes[1].file: unknown mesh format \".txt\" (allowed: .obj, .ply)"}},
        {"OBJ index out of range", meshFile("bad-index.obj"),
         {"meshes[1].file: ", "bad-index.obj: face 0: vertex index 4 (1-based) is out of range"}},
        {"OBJ NaN vertex", meshFile("nan.obj"), {"meshes[1].file: ", "nan.obj: line 2: vertex x \"nan\""}},
        {"PLY truncated", meshFile("truncated.ply"), {"meshes[1].file: ", "truncated.ply: element vertex 1: truncated"}},
        {"PLY index out of range", meshFile("bad-index.ply"),
         {"meshes[1].file: ", "bad-index.ply: element face 0: vertex index 3 is out of range"}},
        {"no instances", [](json& s) { s["instances"] = json::array(); }, {"the scene has no triangles"}},
        {"only a mesh without faces", [](json& s) {
             s["meshes"][1]["file"] = "no-faces.obj";
             s["instances"].erase(0);
         }, {"the scene has no triangles"}},
    });
}

TEST_CASE("environment maps: the path resolved against the scene file, the rotation in range") {
    const test::TempDir dir;
    writeMeshFiles(dir);
    dir.write("sky.hdr", "#?RADIANCE\n");   // only opened here; its contents are the shading library's
    json scene = validScene();
    scene["environment"]["map"] = "sky.hdr";
    scene["environment"]["rotation"] = 30;
    const Scene loaded = loadScene(dir.write("scene.json", render(scene)));
    CHECK(loaded.environment.map == (std::filesystem::path(dir.path("scene.json")).parent_path() / "sky.hdr").string());
    CHECK(loaded.environment.rotationDeg == 30.0f);
    CHECK(loadScene(dir.write("scene.json", render(validScene()))).environment.map.empty());
    checkCases({
        {"missing map", [](json& s) { s["environment"]["map"] = "none.exr"; }, {"environment.map: ", "none.exr: cannot open"}},
        {"map is a directory", [](json& s) { s["environment"]["map"] = "folder.obj"; }, {"environment.map: ", "is a directory"}},
        {"rotation out of range", [](json& s) {
             s["environment"]["map"] = "tri.obj";
             s["environment"]["rotation"] = 400;
         }, {"environment.rotation: "}},
        {"rotation without a map", [](json& s) { s["environment"]["rotation"] = 10; }, {"environment.rotation: turns the map, so needs \"map\""}},
    });
}

TEST_CASE("scene files that cannot be read at all") {
    const test::TempDir dir;
    const std::string broken = dir.write("broken.json", "{\"meshes\": [{\"name\": \"a\",}]}");
    test::checkMessage(test::sceneErrorOf([&] { loadScene(broken); }), {broken + ": meshes[0].name: invalid JSON", "line 1, column 26"});
    const std::string missing = dir.path("absent.json");
    test::checkMessage(test::sceneErrorOf([&] { loadScene(missing); }), {missing + ": cannot open"});
    test::checkMessage(test::sceneErrorOf([&] { loadScene("not-a-built-in"); }),
                       {"unknown scene \"not-a-built-in\"", "sphere-box"});
}

TEST_CASE("JSON nested past the limit is refused while parsing (200000 levels crashed the loader)") {
    const test::TempDir dir;
    const std::string deep = dir.write("deep.json", std::string(200000, '[') + std::string(200000, ']'));
    test::checkMessage(test::sceneErrorOf([&] { loadScene(deep); }), {deep + ": [0][0]", "nested deeper than 64 levels"});
    // A scene nested to the limit is refused by its fields, not its depth.
    const std::string atLimit = dir.write("limit.json", "{\"meshes\": " + std::string(63, '[') + std::string(63, ']') + "}");
    const std::string message = test::sceneErrorOf([&] { loadScene(atLimit); });
    CHECK(message.find("nested deeper") == std::string::npos);
}

TEST_CASE("casters that are not opaque load: translucent and cut-out materials, hair, volumes") {
    const test::TempDir dir;
    writeMeshFiles(dir);
    json s = validScene();
    s["meshes"].push_back({{"name", "hair"}, {"procedural", "hair"}, {"size", {1, 0.2, 0.5}}, {"strands", 50},
                           {"width", 0.004}, {"segments", 4}, {"seed", 3}});
    s["materials"].push_back({{"name", "glass"}, {"opacity", 0.25}, {"transmittance", {0.2, 0.8, 0.3}}});
    s["materials"].push_back({{"name", "leaf"}, {"alpha-texture", "leaf.png"}, {"alpha-cutoff", 0.4}, {"albedo-texture", "leaf.png"}});
    s["instances"].push_back({{"mesh", "hair"}, {"material", "glass"}});
    s["instances"].push_back({{"mesh", "ground"}, {"material", "leaf"}, {"translate", {0, 2, 0}}});
    s["volumes"] = {{{"name", "puff"}, {"procedural", "smoke-puff"}, {"min", {-1, 0, -1}}, {"max", {1, 2, 1}},
                     {"resolution", 8}, {"density", 2}},
                    {{"name", "slab"}, {"procedural", "constant"}, {"min", {-1, 0, -1}}, {"max", {1, 2, 1}}, {"density", 0.5}}};
    const Scene scene = loadScene(dir.write("scene.json", render(s)));
    REQUIRE(scene.materials.size() == 4);
    CHECK(scene.materials[2].passed() == glm::vec3(0.75f) * glm::vec3(0.2f, 0.8f, 0.3f));
    REQUIRE(scene.alphaTextures.size() == 1);
    CHECK(scene.materials[3].alphaTexture == 0);
    CHECK(scene.alphaTextures[0].alpha == std::vector<float>{0.0f, 0.0f, 1.0f, 1.0f, 0.0f, 0.0f, 1.0f, 1.0f});
    // The same file's colour as the albedo texture: sRGB 200 decoded, its alpha not read.
    REQUIRE(scene.albedoTextures.size() == 1);
    CHECK(scene.materials[3].albedoTexture == 0);
    CHECK(scene.albedoTextures[0].albedo == std::vector<glm::vec3>(8, glm::vec3(srgbToLinear(200))));
    CHECK(scene.meshes[4].triangles.size() == 2 * 50 * 4);
    REQUIRE(scene.volumes.size() == 2);
    CHECK(scene.volumes[0].sigma.size() == 8 * 8 * 8);
    CHECK(scene.volumes[1].sigma == std::vector<float>{0.5f});
    CHECK(hasNonOpaqueCasters(scene));
    CHECK(!hasNonOpaqueCasters(loadScene(dir.write("plain.json", render(validScene())))));
}

TEST_CASE("mistakes in casters that are not opaque") {
    const auto withMaterial = [](json material) {
        return [material](json& s) { s["materials"][0].update(material); };
    };
    const json puff = {{"name", "puff"}, {"procedural", "smoke-puff"}, {"min", {-1, 0, -1}}, {"max", {1, 2, 1}},
                       {"resolution", 8}, {"density", 2}};
    const auto withVolume = [puff](json change) {
        return [puff, change](json& s) {
            json volume = puff;
            volume.update(change);
            s["volumes"] = json::array({volume});   // {volume} alone is the object itself on clang
        };
    };
    checkCases({
             {"opacity above 1", withMaterial({{"opacity", 1.5}}), {"materials[0].opacity: must be in [0, 1]"}},
             {"tint without opacity", withMaterial({{"transmittance", {1, 0, 0}}}),
              {"materials[0].transmittance: tints the light a translucent surface passes, so needs \"opacity\" < 1"}},
             {"cutoff without texture", withMaterial({{"alpha-cutoff", 0.5}}),
              {"materials[0].alpha-cutoff: is the cut-out's threshold, so needs \"alpha-texture\""}},
             {"texture without alpha", withMaterial({{"alpha-texture", "grey.png"}}),
              {"materials[0].alpha-texture: ", "grey.png: has no alpha channel"}},
             {"missing texture", withMaterial({{"alpha-texture", "none.png"}}), {"materials[0].alpha-texture: ", "none.png: cannot open"}},
             {"cut-out mesh without uvs",
              [](json& s) { s["materials"][1]["alpha-texture"] = "leaf.png"; },
              {"instances: instance", "has a cut-out material (alpha-texture) on a mesh without texture coordinates"}},
             {"missing albedo texture", withMaterial({{"albedo-texture", "none.png"}}),
              {"materials[0].albedo-texture: ", "none.png: cannot open"}},
             {"albedo texture on a mesh without uvs",
              [](json& s) { s["materials"][1]["albedo-texture"] = "leaf.png"; },
              {"instances: instance", "has a material with an albedo-texture on a mesh without texture coordinates"}},
             {"flat volume", withVolume({{"max", {1, 0, 1}}}), {"volumes[0].max: must be greater than min in x, y and z"}},
             {"huge volume", withVolume({{"resolution", 1000}}), {"volumes[0].resolution: must be in [1, 256]"}},
             {"negative density", withVolume({{"density", -1}}), {"volumes[0].density: must be >= 0"}},
             {"unknown volume kind", withVolume({{"procedural", "cloud"}}), {"volumes[0].procedural: ", "cloud"}},
             {"hair without strands", [](json& s) {
                  s["meshes"].push_back({{"name", "hair"}, {"procedural", "hair"}, {"size", {1, 1, 1}}, {"width", 0.01}});
              }, {"meshes[4]: missing required field \"strands\""}},
    });
}

// The voxel budget is spent before a volume is made (a 256^3 puff took 1.8 s to be refused):
// with the budget already full, even a puff of one voxel is refused, and one of 256^3 is
// refused without its 2^24 voxels being generated.
TEST_CASE("scene limits: a volume's voxels are counted before they are made") {
    const json puff = {{"name", "puff"}, {"procedural", "smoke-puff"}, {"min", {-1, 0, -1}}, {"max", {1, 2, 1}},
                       {"resolution", 1}, {"density", 2}};
    uint64_t voxels = kMaxSceneVoxels;
    test::checkMessage(test::sceneErrorOf([&] { readVolume(JsonField(puff, "s.json", "volumes[1]"), voxels); }),
                       {"s.json: volumes[1]: the volumes hold more than 16777216 voxels together"});
    json big = puff;
    big["resolution"] = 256;
    voxels = 1;
    test::checkMessage(test::sceneErrorOf([&] { readVolume(JsonField(big, "s.json", "volumes[1]"), voxels); }),
                       {"the volumes hold more than 16777216 voxels together"});
    voxels = 0;
    CHECK(readVolume(JsonField(puff, "s.json", "volumes[0]"), voxels).sigma.size() == 1);
    CHECK(voxels == 1);
}
