// KHR_lights_punctual lights read from a glTF file light a plane as the extension's
// recommended formulas say (its README, "Range Property" and "Inner and Outer Cone
// Angles"), computed here from the file's own numbers (radians, candela, lux), apart from
// our conversion to degrees.
#include <algorithm>
#include <cmath>

#include <doctest/doctest.h>

#include "scenes/gltf_scene.h"
#include "shading/lights.h"
#include "tests/scenes/gltf_test_files.h"
#include "tests/scenes/scene_test_files.h"

using namespace shadowlab;

namespace {

constexpr double kInner = 0.3, kOuter = 0.7, kRange = 6.0;

Scene litPlane() {
    test::GltfFile file;
    file.node({{"mesh", file.mesh({{"attributes", {{"POSITION", file.vec3s({{-10, 0, 10}, {10, 0, 10}, {0, 0, -10}})}}}})}});
    file.json["extensions"]["KHR_lights_punctual"]["lights"] = {
        {{"type", "point"}, {"intensity", 30}, {"range", kRange}},
        {{"type", "spot"}, {"intensity", 50}, {"color", {1, 0.5, 0.25}}, {"spot", {{"innerConeAngle", kInner}, {"outerConeAngle", kOuter}}}},
        {{"type", "directional"}, {"intensity", 4}}};
    const double h = std::sqrt(0.5);
    for (int k = 0; k < 3; ++k)   // 4 m above the plane, each turned to shine straight down (-Z to -Y)
        file.node({{"translation", {0, 4, 0}}, {"rotation", {-h, 0, 0, h}}, {"extensions", {{"KHR_lights_punctual", {{"light", k}}}}}});
    test::TempDir dir;
    return loadGltfScene(dir.write("lights.gltf", file.gltf()));
}

double clamp01(double x) { return std::clamp(x, 0.0, 1.0); }

}  // namespace

TEST_CASE("glTF point, spot and directional lights light a plane as KHR_lights_punctual's formulas say") {
    const Scene scene = litPlane();
    REQUIRE(scene.lights.size() == 3);
    const glm::dvec3 light(0, 4, 0), spotDirection(0, -1, 0);
    size_t falloff = 0, beyondRange = 0;
    for (int i = 0; i <= 40; ++i) {
        const glm::vec3 p(float(i) * 0.2f, 0.0f, float(i % 5) * 0.1f);
        const glm::dvec3 toPoint = glm::dvec3(p) - light;
        const double d = glm::length(toPoint);
        INFO("point ", p.x, " 0 ", p.z);
        // Point: I max(min(1 - (d / range)^4, 1), 0) / d^2.
        const double pointExpected = 30.0 * std::max(std::min(1.0 - std::pow(d / kRange, 4.0), 1.0), 0.0) / (d * d);
        CHECK(lightArrival(scene.lights[0], p).irradiance.x == doctest::Approx(pointExpected).epsilon(1e-5));
        beyondRange += pointExpected == 0.0;
        // Spot: scale = 1 / max(0.001, cos(inner) - cos(outer)), offset = -cos(outer) scale,
        // attenuation = saturate(cd scale + offset)^2, cd the cosine to the axis.
        const double scale = 1.0 / std::max(0.001, std::cos(kInner) - std::cos(kOuter));
        const double offset = -std::cos(kOuter) * scale;
        const double cd = glm::dot(spotDirection, toPoint / d);
        const double attenuation = clamp01(cd * scale + offset) * clamp01(cd * scale + offset);
        const glm::vec3 spot = lightArrival(scene.lights[1], p).irradiance;
        CHECK(spot.x == doctest::Approx(50.0 * attenuation / (d * d)).epsilon(1e-5));
        CHECK(spot.z == doctest::Approx(0.25 * 50.0 * attenuation / (d * d)).epsilon(1e-5));
        falloff += attenuation > 0.0 && attenuation < 1.0;
        // Directional: the lux as W/m^2, whatever the distance.
        CHECK(lightArrival(scene.lights[2], p).irradiance == glm::vec3(4.0f));
    }
    CHECK(falloff >= 5);       // the samples cross the spot's smooth edge
    CHECK(beyondRange >= 5);   // and pass the point light's range
}

TEST_CASE("a spot without an inner angle and a light without a range keep the plain rules' bits") {
    Light spot;
    spot.type = LightType::Spot;
    spot.position = glm::vec3(0, 4, 0);
    spot.coneAngleDeg = 40.0f;
    spot.intensity = glm::vec3(50.0f);
    const glm::vec3 p(1.0f, 0.0f, 0.5f);
    const glm::dvec3 toPoint = glm::dvec3(p) - glm::dvec3(spot.position);
    // The hard cone's I / d^2, in double, rounded once.
    const float expected = float(50.0 / glm::dot(toPoint, toPoint));
    CHECK(lightArrival(spot, p).irradiance.x == expected);
    spot.innerConeAngleDeg = 10.0f;
    CHECK(lightArrival(spot, p).irradiance.x < expected);
}
