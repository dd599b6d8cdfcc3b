// Shading against hand computations: Lambert, normalised Blinn-Phong at the mirror
// configuration, spot cone, directional and area lights as far-field point lights.
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "raster/portable_constants.h"
#include "shading/lights.h"
#include "shading/shade.h"

using namespace shadowlab;

namespace {

// One pixel at the origin looking up (N = +Y), one background pixel.
GBuffer onePointAtOrigin(uint32_t material) {
    GBuffer g;
    g.width = 2;
    g.height = 1;
    g.hit = {1, 0};
    g.position = {glm::vec3(0.0f), glm::vec3(0.0f)};
    g.normal = {glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(0.0f)};
    g.shadingNormal = g.normal;
    g.material = {material, 0};
    g.triangle = {0, kNoTriangle};
    g.depth = {0.5f, 1.0f};
    return g;
}

Scene sceneWith(const Light& light) {
    Scene s;
    Material lambert;
    lambert.albedo = {0.5f, 0.25f, 1.0f};
    Material phong;
    phong.model = MaterialModel::BlinnPhong;
    phong.albedo = {0.2f, 0.4f, 0.6f};
    phong.specular = {0.5f, 0.5f, 0.25f};
    phong.shininess = 16.0f;
    s.materials = {lambert, phong};
    s.lights = {light};
    s.environment.ambient = {0.1f, 0.2f, 0.3f};
    s.camera.eye = {-2.0f, 2.0f, 0.0f};
    return s;
}

void checkColour(const glm::vec3& actual, const glm::dvec3& expected) {
    for (int c = 0; c < 3; ++c) {
        CHECK(actual[c] == doctest::Approx(expected[c]).epsilon(1e-6));
    }
}

}  // namespace

TEST_CASE("Lambert under a point light matches albedo/pi * I cos / d^2, scaled by V") {
    Light light;
    light.type = LightType::Point;
    light.position = {1.0f, 2.0f, 0.5f};
    light.intensity = {10.0f, 20.0f, 5.0f};
    const Scene scene = sceneWith(light);
    const GBuffer g = onePointAtOrigin(0);
    const glm::dvec3 albedo(0.5, 0.25, 1.0), ambient(0.1, 0.2, 0.3);
    const double d2 = 1.0 + 4.0 + 0.25, cosTheta = 2.0 / std::sqrt(d2);
    const glm::dvec3 direct = albedo / kPi * glm::dvec3(10.0, 20.0, 5.0) * (cosTheta / d2);

    const std::vector<glm::vec3> half = shade(scene, g, 0, {0.5f, 1.0f});
    checkColour(half[0], ambient * albedo + 0.5 * direct);
    CHECK(half[1] == glm::vec3(0.0f));  // background
    const std::vector<glm::vec3> dark = shade(scene, g, 0, {0.0f, 0.0f});
    checkColour(dark[0], ambient * albedo);
}

TEST_CASE("normalised Blinn-Phong at the mirror direction adds specular*(s+8)/(8 pi)") {
    Light light;
    light.position = {1.0f, 1.0f, 0.0f};  // mirror of the eye (-2, 2, 0) direction: H = N
    light.intensity = {4.0f, 4.0f, 4.0f};
    const Scene scene = sceneWith(light);
    const glm::dvec3 albedo(0.2, 0.4, 0.6), specular(0.5, 0.5, 0.25), ambient(0.1, 0.2, 0.3);
    const glm::dvec3 f = albedo / kPi + specular * ((16.0 + 8.0) / (8.0 * kPi));
    const double irradiance = 4.0 / 2.0 * (1.0 / std::sqrt(2.0));  // I / d^2 * cos
    checkColour(shade(scene, onePointAtOrigin(1), 0, {1.0f, 0.0f})[0], ambient * albedo + f * irradiance);
}

TEST_CASE("spot light is a hard cone, directional light gives E cos") {
    Light spot;
    spot.type = LightType::Spot;
    spot.position = {0.0f, 2.0f, 0.0f};
    spot.direction = {1.0f, -1.0f, 0.0f};  // axis 45 degrees from the point's direction
    spot.coneAngleDeg = 40.0f;
    const Scene outside = sceneWith(spot);
    const glm::dvec3 ambientOnly = glm::dvec3(0.1, 0.2, 0.3) * glm::dvec3(0.5, 0.25, 1.0);
    checkColour(shade(outside, onePointAtOrigin(0), 0, {1.0f, 0.0f})[0], ambientOnly);
    CHECK_FALSE(insideSpotCone(spot, glm::vec3(0.0f)));
    spot.coneAngleDeg = 50.0f;
    CHECK(insideSpotCone(spot, glm::vec3(0.0f)));

    Light sun;
    sun.type = LightType::Directional;
    sun.direction = {0.0f, 2.0f, 2.0f};  // towards the light, not normalised: cos = 1/sqrt(2)
    sun.intensity = {3.0f, 3.0f, 3.0f};
    const glm::dvec3 albedo(0.5, 0.25, 1.0);
    checkColour(shade(sceneWith(sun), onePointAtOrigin(0), 0, {1.0f, 0.0f})[0],
                ambientOnly + albedo / kPi * 3.0 / std::sqrt(2.0));
    // A sun with a size shades as the point-like one, bit for bit: E from its centre, times
    // V (conventions.md, "Lights"); its size shows only in the soft reference's V.
    Light sized = sun;
    sized.angularDiameterDeg = 2.5f;
    const std::vector<glm::vec3> point = shade(sceneWith(sun), onePointAtOrigin(0), 0, {0.5f, 0.0f});
    const std::vector<glm::vec3> disk = shade(sceneWith(sized), onePointAtOrigin(0), 0, {0.5f, 0.0f});
    CHECK(point == disk);
}

TEST_CASE("disk and rectangle lights shade as point lights of intensity L A cos(theta_light)") {
    const glm::dvec3 albedo(0.5, 0.25, 1.0), ambientOnly = glm::dvec3(0.1, 0.2, 0.3) * albedo;
    GBuffer g = onePointAtOrigin(0);
    g.position[0] = {1.0f, 0.0f, 0.0f};
    const double d2 = 5.0, cosLight = 2.0 / std::sqrt(5.0), cosSurface = 2.0 / std::sqrt(5.0);

    Light disk;
    disk.type = LightType::Disk;
    disk.position = {0.0f, 2.0f, 0.0f};
    disk.direction = {0.0f, -1.0f, 0.0f};
    disk.radius = 0.5f;
    disk.intensity = {2.0f, 2.0f, 2.0f};
    const double diskIntensity = 2.0 * kPi * 0.25 * cosLight;
    checkColour(shade(sceneWith(disk), g, 0, {1.0f, 0.0f})[0],
                ambientOnly + albedo / kPi * diskIntensity * cosSurface / d2);

    Light rectangle = disk;
    rectangle.type = LightType::Rectangle;
    rectangle.halfEdgeU = {0.5f, 0.0f, 0.0f};
    rectangle.halfEdgeV = {0.0f, 0.0f, 0.25f};  // U x V points down: emits towards the floor
    CHECK(areaLightNormal(rectangle) == glm::dvec3(0.0, -1.0, 0.0));
    CHECK(areaLightArea(rectangle) == doctest::Approx(0.5));
    const double rectangleIntensity = 2.0 * 0.5 * cosLight;
    checkColour(shade(sceneWith(rectangle), g, 0, {1.0f, 0.0f})[0],
                ambientOnly + albedo / kPi * rectangleIntensity * cosSurface / d2);

    std::swap(rectangle.halfEdgeU, rectangle.halfEdgeV);  // now emits upwards: floor is dark
    checkColour(shade(sceneWith(rectangle), g, 0, {1.0f, 0.0f})[0], ambientOnly);
}

TEST_CASE("shade rejects a bad light index, visibility size or G-buffer") {
    const Scene scene = sceneWith(Light{});
    const GBuffer g = onePointAtOrigin(0);
    CHECK_THROWS_AS(shade(scene, g, 1, {1.0f, 1.0f}), std::out_of_range);
    CHECK_THROWS_AS(shade(scene, g, 0, {1.0f}), std::invalid_argument);
    GBuffer shortNormals = g;
    shortNormals.normal.pop_back();
    CHECK_THROWS_AS(shade(scene, shortNormals, 0, {1.0f, 1.0f}), std::invalid_argument);
}
