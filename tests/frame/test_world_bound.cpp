// The world's bound (scenes/scene_limits.h, kMaxCoordinate): a position beyond it is
// refused where it is read, on the command line as in a file, and at the bound every
// technique still renders a finite frame (a light at 1.9e18 m aborted inside Embree).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "frame/registry.h"
#include "frame/render.h"
#include "scenes/camera_path.h"
#include "scenes/scene_limits.h"
#include "tests/frame/technique_scenes.h"

using namespace shadowlab;

namespace {

SceneOverrides lightAt(const glm::vec3& position) {
    SceneOverrides overrides;
    overrides.lightPosition = position;
    return overrides;
}

bool allFinite(const std::vector<float>& values) {
    return std::ranges::all_of(values, [](float v) { return std::isfinite(v); });
}

}  // namespace

TEST_CASE("world bound: a position beyond it on the command line is refused") {
    const float bound = float(kMaxCoordinate);
    for (const glm::vec3& far : {glm::vec3(1.9e18f, 5.0f, 0.0f), glm::vec3(0.0f, 2.0f * bound, 0.0f),
                                 glm::vec3(0.0f, std::numeric_limits<float>::quiet_NaN(), 0.0f)}) {
        Scene scene = test::smallScene("sphere-box");
        CHECK_THROWS_WITH_AS(applyOverrides(scene, lightAt(far)), doctest::Contains("--light-pos must be three numbers within"),
                             std::invalid_argument);
        SceneOverrides eye;
        eye.eye = far;
        CHECK_THROWS_WITH_AS(applyOverrides(scene, eye), doctest::Contains("--eye must be three numbers within"),
                             std::invalid_argument);
    }
}

TEST_CASE("world bound: at the bound every technique renders a finite frame") {
    const float bound = float(kMaxCoordinate);
    Scene disk = test::smallScene("sphere-box", 48, 30);
    applyOverrides(disk, lightAt({-bound, bound, 0.5f * bound}));
    Scene sun = test::smallScene(test::sunScene(), 48, 30), sky = test::smallScene(test::skyScene(), 48, 30);
    for (Scene* s : {&sun, &sky}) s->camera.eye = glm::vec3(bound, s->camera.eye.y, s->camera.eye.z);
    for (Scene* s : {&sun, &sky}) s->camera.target = glm::vec3(bound - 1.0f, s->camera.target.y, s->camera.target.z);
    const PreparedScene preparedDisk(disk), preparedSun(sun), preparedSky(sky);
    for (const Technique& t : techniques()) {
        INFO(t.name);
        FrameSettings settings;
        settings.params = test::quickSettings(t);
        const PreparedScene& scene = t.output == TechniqueOutput::Radiance ? preparedSky
                                     : test::runsOnASun(t) || t.name == "shadow-map" ? preparedSun
                                                                                                   : preparedDisk;
        const Frame frame = renderFrame(scene, t, settings);
        CHECK(allFinite(frame.shadow.visibility));
    }
}

TEST_CASE("world bound: a path's keys are bound and interpolate without overflow") {
    const std::vector<Light> noLights;
    CHECK_THROWS_WITH_AS(parseCameraPathCsv("time,eye_x,eye_y,eye_z,target_x,target_y,target_z\n0,0,1,2e6,0,0,0\n",
                                            "far.csv", noLights),
                         doctest::Contains("eye_z: must be in [-1e+06, 1e+06] (metres), got '2e6'"), SceneError);
    const CameraPath path = parseCameraPathCsv(
        "time,eye_x,eye_y,eye_z,target_x,target_y,target_z\n0,-1e6,1,-1e6,0,0,0\n1,1e6,1,1e6,0,0,1\n", "wide.csv", noLights);
    const PathSample middle = samplePath(path, 1, 3);
    CHECK(middle.eye == glm::vec3(0.0f, 1.0f, 0.0f));
    CHECK(samplePath(path, 2, 3).eye == glm::vec3(1e6f, 1.0f, 1e6f));   // the last key exactly
}
