// Cube-face culling (docs/many-lights.md): a point light's cube face whose pyramid holds no
// visible receiver is not drawn. Over light positions inside and outside the view on three
// scenes, V with culling (cube-faces=visible) equals V with all six faces drawn
// (cube-faces=all) bit for bit, so no culled face could have shadowed a visible pixel; and
// some faces are culled, so the comparison is not between two identical runs.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "tests/same_bits.h"
#include "tests/shadows/maps/shadow_map_test_util.h"

using namespace shadowlab;

namespace {

struct CullingCase {
    std::string scene;
    std::vector<glm::vec3> lightPositions;
};

// The scene at a small size, its first light a point light at `position`.
Scene pointLitAt(const std::string& path, const glm::vec3& position) {
    Scene scene = loadScene(path);
    scene.camera.width = 120, scene.camera.height = 75;
    Light point = scene.lights.at(0);
    point.type = LightType::Point;
    point.position = position;
    scene.lights = {point};
    return scene;
}

}  // namespace

TEST_CASE("cube-face culling: V with the faces no visible receiver lies in culled equals V with all six drawn") {
    const std::string dir = std::string(SHADOWLAB_SOURCE_DIR) + "/assets/scenes/";
    const std::vector<CullingCase> cases = {
        // Among the casters (the scene's own), above them, near the camera, behind the camera
        // (outside the view), behind the casters and under the ground.
        {dir + "many-lights/three-lights.json",
         {{-1.2f, 0.9f, 1.4f}, {0.5f, 3.0f, 3.5f}, {0.0f, 2.0f, 12.0f}, {0.0f, 0.5f, -4.0f}, {3.0f, -1.0f, 0.0f}}},
        // Inside the closed room: its centre and two corners, one by the camera.
        {dir + "hard/point-light-inside.json", {{0.0f, 1.5f, 0.0f}, {2.5f, 0.3f, 2.5f}, {-2.5f, 2.8f, -2.5f}}},
        // sphere-box's light as a point, and one low beside the sphere.
        {"sphere-box", {{4.0f, 8.0f, 3.0f}, {-1.5f, 0.6f, 0.5f}}},
    };
    int culled = 0, lightsCulled = 0;
    for (const CullingCase& c : cases) {
        for (const glm::vec3& position : c.lightPositions) {
            CAPTURE(c.scene);
            INFO("light at " << position.x << ", " << position.y << ", " << position.z);
            const PreparedScene prepared(pointLitAt(c.scene, position));
            const std::map<std::string, std::string> settings = {{"cube", "always"}, {"resolution", "256"}};
            std::map<std::string, std::string> all = settings;
            all["cube-faces"] = "all";
            const Frame visible = test::frameOf(prepared, "shadow-map", settings);
            const Frame everyFace = test::frameOf(prepared, "shadow-map", all);
            CHECK(test::sameBytes(visible.shadow.visibility, everyFace.shadow.visibility));
            CHECK(test::statOf(everyFace, "maps_count") == 6.0);
            const double drawn = test::statOf(visible, "maps_count");
            CHECK(drawn >= 1.0);
            culled += int(6.0 - drawn);
            lightsCulled += drawn < 6.0;
        }
    }
    MESSAGE("cube faces culled: " << culled << " over " << lightsCulled << " light positions");
    CHECK(lightsCulled >= 4);
}
