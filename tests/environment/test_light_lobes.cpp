// Region lobes (compositing/light_lobes.h): a light's lobe widened by its region's solid
// angle as the variances of two Gaussians add, and what that does to subtractive shadows.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "shadows/environment/light_lobes.h"
#include "tests/environment/environment_scenes.h"

using namespace shadowlab;
using namespace shadowlab::test;

TEST_CASE("region lobes: each model's lobe widens by the cap's variance, the diffuse term stays") {
    const std::vector<Material> materials = {
        {.name = "lambert", .albedo = glm::vec3(0.5f)},
        {.name = "phong", .model = MaterialModel::Phong, .shininess = 40.0f},
        {.name = "blinn", .model = MaterialModel::BlinnPhong, .shininess = 100.0f},
        {.name = "ggx", .model = MaterialModel::Ggx, .roughness = 0.2f},
        {.name = "rough", .model = MaterialModel::Ggx, .roughness = 0.999f}};
    // A cap of angular radius rho = 0.2 rad.
    const double rho = 0.2, omega = 2.0 * std::numbers::pi * (1.0 - std::cos(rho));
    const std::vector<Material> wide = widenedForRegion(materials, omega);
    CHECK(wide[0].albedo == materials[0].albedo);
    CHECK(wide[1].shininess == doctest::Approx(1.0 / (1.0 / 40.0 + rho * rho / 4.0)).epsilon(1e-5));
    CHECK(wide[2].shininess == doctest::Approx(1.0 / (1.0 / 100.0 + rho * rho / 16.0)).epsilon(1e-5));
    CHECK(wide[3].roughness == doctest::Approx(std::sqrt(0.04 + rho * rho / 4.0)).epsilon(1e-5));
    CHECK(wide[4].roughness == 1.0f);
    // A point region changes nothing.
    const std::vector<Material> same = widenedForRegion(materials, 0.0);
    for (size_t k = 0; k < materials.size(); ++k) {
        CHECK(same[k].shininess == materials[k].shininess);
        CHECK(same[k].roughness == materials[k].roughness);
    }
}

TEST_CASE("region lobes: subtractive shadows clamp fewer pixels on the glossy bunny, and the furnace stays exact") {
    Scene bunny = loadScene(std::string(SHADOWLAB_SOURCE_DIR) + "/assets/scenes/environment/bunny-interior.json");
    bunny.camera.width = 128, bunny.camera.height = 80;
    const PreparedScene prepared(bunny);
    double clamped[2] = {0.0, 0.0};
    for (int lobes = 0; lobes < 2; ++lobes) {
        clamped[lobes] = stat(frameOf(prepared, "env-subtractive", {{"lights", "40"}, {"light-lobes", lobes ? "region" : "point"}}),
                              "clamped_pixels");
    }
    MESSAGE("clamped pixels: point " << clamped[0] << ", region " << clamped[1]);
    CHECK(clamped[1] < 0.8 * clamped[0]);   // measured 102 and 70 at 128 x 80

    const ScratchDirectory dir("lobes-furnace");
    const PreparedScene open(furnaceScene(writeConstantMap(dir, kFurnaceRadiance), false));
    const Frame point = frameOf(open, "env-additive", {{"lights", "64"}, {"visibility", "exact"}});
    const Frame region = frameOf(open, "env-additive", {{"lights", "64"}, {"visibility", "exact"}, {"light-lobes", "region"}});
    CHECK(point.radiance == region.radiance);   // Lambert: no lobe to widen
}
