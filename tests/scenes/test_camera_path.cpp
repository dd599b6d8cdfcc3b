// Camera paths (scenes/camera_path.h): sampling at evenly spaced times, linear between the
// keyframes around a frame and exact at a keyframe's own time; and every mistake in a
// scene file's "flythrough" or a keyframe CSV reported where it is.
#include <doctest/doctest.h>

#include "scenes/camera.h"
#include "scenes/camera_path.h"
#include "scenes/scene_file.h"
#include "tests/scenes/scene_test_files.h"

using namespace shadowlab;

namespace {

// A one-triangle scene with one light of the given kind and the given "flythrough" value.
std::string sceneWithPath(const std::string& flythrough, bool sun = false) {
    const std::string light = sun ? R"({"type": "directional", "direction": [0, 1, 0], "power": 3})"
                                  : R"({"type": "point", "position": [0, 5, 0], "power": 10})";
    return R"({"meshes": [{"name": "ground", "procedural": "grid", "size": [2, 2], "divisions": [1, 1]}],
               "materials": [{"name": "white", "model": "lambert", "albedo": [0.8, 0.8, 0.8]}],
               "instances": [{"mesh": "ground", "material": "white"}],
               "lights": [)" + light + R"(],
               "camera": {"eye": [0, 4, 9], "target": [0, 0, 0], "fovy": 45, "width": 64, "height": 40},
               "flythrough": )" + flythrough + "}";
}

CameraPath threeKeyframes() {
    CameraPath path;
    path.keyframes = {{0.0, {0, 4, 9}, {0, 0, 0}, glm::vec3(0, 5, 0), {}},
                      {1.0, {4, 4, 5}, {0, 1, 0}, glm::vec3(2, 5, 0), {}},
                      {3.0, {8, 2, 1}, {1, 1, 1}, glm::vec3(2, 5, 4), {}}};
    return path;
}

}  // namespace

TEST_CASE("a path's frames are evenly spaced in time, exact at keyframes and linear between them") {
    const CameraPath path = threeKeyframes();
    // 7 frames over 3 time units: frame 2 lands on keyframe 1's time, frame 6 on the last.
    const PathSample atKey = samplePath(path, 2, 7);
    CHECK(atKey.time == 1.0);
    CHECK(atKey.eye == glm::vec3(4, 4, 5));
    CHECK(atKey.light == glm::vec3(2, 5, 0));
    CHECK(samplePath(path, 6, 7).eye == glm::vec3(8, 2, 1));
    CHECK(samplePath(path, 0, 7).eye == glm::vec3(0, 4, 9));
    // Frame 1 at t = 0.5, half way between keyframes 0 and 1; frame 4 at t = 2, half way on [1, 3].
    const PathSample half = samplePath(path, 1, 7);
    CHECK(half.eye == glm::vec3(2, 4, 7));
    CHECK(half.target == glm::vec3(0, 0.5f, 0));
    CHECK(samplePath(path, 4, 7).eye == glm::vec3(6, 3, 3));
    CHECK(samplePath(path, 4, 7).light == glm::vec3(2, 5, 2));
    // One frame is the first keyframe.
    CHECK(samplePath(path, 0, 1).eye == glm::vec3(0, 4, 9));
}

TEST_CASE("a directional light's path is interpolated, then normalised, and placed on the light") {
    CameraPath path;
    path.keyframes = {{0.0, {0, 4, 9}, {0, 0, 0}, glm::vec3(2, 0, 0), {}}, {1.0, {0, 4, 9}, {0, 0, 0}, glm::vec3(0, 2, 0), {}}};
    const PathSample mid = samplePath(path, 1, 3);
    CHECK(mid.light == glm::vec3(1, 1, 0));
    Camera camera;
    std::vector<Light> lights(1);
    lights[0].type = LightType::Directional;
    lights[0].angularDiameterDeg = 2.5f;
    placeOnPath(mid, 1, camera, lights);
    CHECK(glm::length(lights[0].direction) == doctest::Approx(1.0).epsilon(1e-6));
    CHECK(lights[0].direction.x == lights[0].direction.y);
    CHECK(lights[0].angularDiameterDeg == 2.5f);   // turning the sun keeps its size
    CHECK(camera.eye == glm::vec3(0, 4, 9));
    // The eye passing through the target between two keyframes is caught at that frame.
    // Frame 1 of 3 has its eye and its target both at (0, 0, 1).
    path.keyframes = {{0.0, {0, 0, 2}, {0, 0, 3}, {}, {}}, {1.0, {0, 0, 0}, {0, 0, -1}, {}, {}}};
    CHECK_THROWS_WITH_AS(placeOnPath(samplePath(path, 1, 3), 1, camera, lights),
                         doctest::Contains("frame 1 of the path"), std::invalid_argument);
}

TEST_CASE("a scene file's flythrough loads, and every mistake in it names its field") {
    const Scene scene = parseScene(sceneWithPath(R"({"frames": 12, "keyframes": [
        {"time": 0, "eye": [0, 4, 9], "target": [0, 0, 0], "light_position": [0, 5, 0]},
        {"time": 2, "eye": [1, 4, 9], "target": [0, 0, 0], "light_position": [1, 5, 0]}]})"), "path.json");
    CHECK(scene.flythrough.frames == 12);
    REQUIRE(scene.flythrough.keyframes.size() == 2);
    CHECK(scene.flythrough.keyframes[1].time == 2.0);
    CHECK(scene.flythrough.keyframes[1].light == glm::vec3(1, 5, 0));
    const auto errorOf = [](const std::string& flythrough, bool sun = false) {
        return test::sceneErrorOf([&] { parseScene(sceneWithPath(flythrough, sun), "path.json"); });
    };
    const std::string key0 = R"({"time": 0, "eye": [0, 4, 9], "target": [0, 0, 0]})";
    test::checkMessage(errorOf(R"({"keyframes": []})"), {"path.json", "flythrough.keyframes", "at least one"});
    test::checkMessage(errorOf(R"({"frames": 1, "keyframes": [)" + key0 + "]}"), {"flythrough.frames"});
    test::checkMessage(errorOf(R"({"keyframes": [)" + key0 + "," + key0 + "]}"),
                       {"flythrough.keyframes[1]", "times must increase"});
    test::checkMessage(errorOf(R"({"keyframes": [{"time": 0, "eye": [0, 0, 0], "target": [0, 0, 0]}]})"),
                       {"keyframes[0]", "eye is on the target"});
    // A point light moves by position, a sun turns by direction; the other key is unknown.
    test::checkMessage(errorOf(R"({"keyframes": [{"time": 0, "eye": [0, 4, 9], "target": [0, 0, 0],
                                   "light_direction": [0, 1, 0]}]})"), {"unknown key", "light_position"});
    test::checkMessage(errorOf(R"({"keyframes": [{"time": 0, "eye": [0, 4, 9], "target": [0, 0, 0],
                                   "light_position": [0, 1, 0]}]})", true), {"unknown key", "light_direction"});
    test::checkMessage(errorOf(R"({"keyframes": [{"time": 0, "eye": [0, 4, 9], "target": [0, 0, 0],
                                   "light_position": [0, 5, 0]},
                                  {"time": 1, "eye": [0, 4, 9], "target": [0, 0, 0]}]})"),
                       {"keyframes[1]", "every keyframe or in none"});
    test::checkMessage(errorOf(R"({"keyframes": [{"time": 0, "eye": [0, 4, 9], "target": [0, 0, 0],
                                   "light_direction": [0, 1, 0]}, {"time": 1, "eye": [0, 4, 9], "target": [0, 0, 0],
                                   "light_direction": [0.01, -1, 0]}]})", true), {"keyframes[1]", "170 degrees"});
    test::checkMessage(errorOf(R"({"keyframes": [{"time": 0, "eye": [0, 4, 9], "target": [0, 0, 0],
                                   "light_direction": [0, 0, 0]}]})", true), {"keyframes[0]", "direction is zero"});
}

TEST_CASE("keyframes read from CSV, and every mistake in the file names its line") {
    std::vector<Light> lights(1);
    const CameraPath path = parseCameraPathCsv(
        "# a comment\n"
        "time,eye_x,eye_y,eye_z,target_x,target_y,target_z,light_position_x,light_position_y,light_position_z\n"
        "0, 0, 4, 9, 0, 0, 0, 0, 5, 0\n"
        "\n"
        "0.5, 1, 4, 9, 0, 0.5, 0, 1, 5, 0\r\n", "keys.csv", lights);
    REQUIRE(path.keyframes.size() == 2);
    CHECK(path.keyframes[1].time == 0.5);
    CHECK(path.keyframes[1].target == glm::vec3(0, 0.5f, 0));
    CHECK(path.keyframes[1].light == glm::vec3(1, 5, 0));
    CHECK(path.frames == 0);
    const std::string header = "time,eye_x,eye_y,eye_z,target_x,target_y,target_z\n";
    const auto errorOf = [&](const std::string& text) {
        return test::sceneErrorOf([&] { parseCameraPathCsv(text, "keys.csv", lights); });
    };
    test::checkMessage(errorOf(""), {"keys.csv", "no header"});
    test::checkMessage(errorOf(header), {"keys.csv", "no keyframes"});
    test::checkMessage(errorOf("time,eye_x\n0,1\n"), {"line 1", "expected the header"});
    test::checkMessage(errorOf(header + "0,0,4,9,0,0\n"), {"line 2", "expected 7 values, got 6"});
    test::checkMessage(errorOf(header + "0,0,4,nine,0,0,0\n"), {"line 2", "eye_z", "'nine'"});
    test::checkMessage(errorOf(header + "0,0,4,9,0,0,inf\n"), {"line 2", "target_z"});
    test::checkMessage(errorOf(header + "0,0,4,1e39,0,0,0\n"), {"line 2", "eye_z"});
    test::checkMessage(errorOf(header + "1,0,4,9,0,0,0\n0,0,4,8,0,0,0\n"), {"line 3", "times must increase"});
    test::checkMessage(errorOf(header + "-1e308,0,4,9,0,0,0\n1e308,0,4,8,0,0,0\n"), {"line 3", "span"});
    // A point light's path names positions; light_direction is for a directional light.
    test::checkMessage(errorOf("time,eye_x,eye_y,eye_z,target_x,target_y,target_z,light_direction_x,"
                               "light_direction_y,light_direction_z\n"), {"line 1", "light_position"});
}
