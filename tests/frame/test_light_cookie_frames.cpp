// Light cookies in whole frames (assets/scenes/cookies/spot-cookie.json): the cookie scales the
// light every technique's image shows, not V, and the scene file refuses bad cookies.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "frame/registry.h"
#include "frame/render.h"
#include "scenes/light_cookie.h"
#include "scenes/scene_file.h"
#include "shading/image_io.h"
#include "shading/lights.h"
#include "tests/scratch_directory.h"

using namespace shadowlab;

namespace {

const std::string kCookieScene = std::string(SHADOWLAB_SOURCE_DIR) + "/assets/scenes/cookies/spot-cookie.json";

// The spot-cookie case as it is and without its cookie.
struct CookiePair {
    PreparedScene cookied{loadScene(kCookieScene)};
    PreparedScene plain{withoutCookie(loadScene(kCookieScene))};
    static Scene withoutCookie(Scene scene) {
        scene.lights[0].cookie = nullptr;
        return scene;
    }
};

// A scene file written to a scratch folder, the blinds' cookie path absolute.
std::string sceneWithLight(const std::string& light) {
    std::string text = R"({"meshes": [{"name": "plane", "procedural": "grid", "size": [4, 4], "divisions": [1, 1]}],
        "materials": [{"name": "grey", "model": "lambert", "albedo": [0.5, 0.5, 0.5]}],
        "instances": [{"mesh": "plane", "material": "grey"}],
        "camera": {"eye": [0, 4, 4], "target": [0, 0, 0], "fovy": 45, "width": 32, "height": 32},
        "lights": [)";
    text += light;
    text += "]}";
    return text;
}

}  // namespace

TEST_CASE("light cookie: every technique's image is the uncookied one where the blinds are open, dark where closed") {
    const CookiePair pair;
    const Light& light = pair.cookied.scene().lights[0];
    REQUIRE(light.cookie != nullptr);
    for (const char* name : {"reference", "shadow-map", "projected-texture"}) {
        const Technique& technique = findTechnique(name);
        const Frame cookied = renderFrame(pair.cookied, technique), plain = renderFrame(pair.plain, technique);
        CHECK(cookied.shadow.visibility == plain.shadow.visibility);   // visibility is not emission
        size_t open = 0, closed = 0, wrong = 0;
        for (size_t k = 0; k < cookied.gbuffer.pixelCount(); ++k) {
            const GBuffer& g = cookied.gbuffer;
            if (!g.hit[k] || !insideSpotCone(light, g.position[k]) || cookied.shadow.visibility[k] == 0.0f) continue;
            // The blinds are 0 or 1 (scripts/make_cookie_texture.py), so the products are exact:
            // the plain radiance where open, the ambient alone where closed.
            const glm::vec3 texel = cookieTransmission(light, g.position[k]);
            const Material& material = pair.cookied.scene().materials[g.material[k]];
            const glm::vec3 ambient = pair.cookied.scene().environment.ambient * material.albedo;
            const glm::vec3 expected = texel.x == 1.0f ? plain.radiance[k] : ambient;
            open += texel.x == 1.0f, closed += texel.x == 0.0f;
            wrong += cookied.radiance[k] != expected;
        }
        INFO(name << ": " << open << " lit pixels under open slats, " << closed << " under closed ones");
        CHECK(open > 5000);
        CHECK(closed > 3000);
        CHECK(wrong == 0);
    }
}

TEST_CASE("light cookie: the scene file refuses a missing cookie and a cookie on a light that is not a spot") {
    const std::string blinds = std::string(SHADOWLAB_SOURCE_DIR) + "/assets/textures/blinds.png";
    const std::string spot = R"({"type": "spot", "position": [0, 4, 0], "direction": [0, -1, 0], "coneAngle": 30,
        "power": 10, "cookie": ")";
    const Scene good = parseScene(sceneWithLight(spot + blinds + "\"}"), "/tmp/cookie-scene.json");
    REQUIRE(good.lights[0].cookie != nullptr);
    CHECK(good.lights[0].cookie->width == 128);
    CHECK(good.lights[0].cookie->texels[0] == glm::vec3(0.0f));                       // the pelmet
    CHECK(good.lights[0].cookie->texels[16 * 128] == glm::vec3(1.0f));                 // an open slat
    CHECK_THROWS_WITH_AS(parseScene(sceneWithLight(spot + "no-such-cookie.png\"}"), "/tmp/cookie-scene.json"),
                         doctest::Contains("lights[0].cookie"), SceneError);
    CHECK_THROWS_WITH_AS(parseScene(sceneWithLight(spot + "no-such-cookie.png\"}"), "/tmp/cookie-scene.json"),
                         doctest::Contains("no-such-cookie.png: cannot open"), SceneError);
    const std::string point = R"({"type": "point", "position": [0, 4, 0], "power": 10, "cookie": ")";
    CHECK_THROWS_WITH_AS(parseScene(sceneWithLight(point + blinds + "\"}"), "/tmp/cookie-scene.json"),
                         doctest::Contains("only a spot light may have one"), SceneError);
    CHECK_THROWS_AS(parseScene(sceneWithLight(spot + "\"}"), "/tmp/cookie-scene.json"), SceneError);   // a folder
}

TEST_CASE("light cookie: an RGB image keeps its channels, each value / 255, row 0 at the top") {
    const test::ScratchDirectory dir("cookie_rgb");
    const std::vector<uint8_t> rgb = {255, 0, 51, 0, 102, 255,    // top row
                                      17, 34, 68, 255, 255, 255};  // bottom row
    writePng(dir.path / "rgb.png", 2, 2, rgb);
    const LightCookie cookie = readLightCookie((dir.path / "rgb.png").string());
    REQUIRE(cookie.width == 2);
    REQUIRE(cookie.height == 2);
    for (size_t k = 0; k < 4; ++k) {
        CHECK(cookie.texels[k] == glm::vec3(float(rgb[3 * k]), float(rgb[3 * k + 1]), float(rgb[3 * k + 2])) / 255.0f);
    }
}
