// Light cookies (shading/lights.h, cookieCoordinates and cookieTransmission): the square
// projection through a spot's cone and its up rule at points worked out by hand, and the
// arrival they scale.
#include <doctest/doctest.h>

#include <memory>

#include "shading/lights.h"

using namespace shadowlab;

namespace {

// 4 x 2 texels, each its own value: row 0 (the top) 0.1 .. 0.4, row 1 0.5 .. 0.8 in red,
// green the same halved, blue 1.
std::shared_ptr<const LightCookie> numberedCookie() {
    LightCookie cookie{"numbered", 4, 2, {}};
    for (int k = 0; k < 8; ++k) cookie.texels.push_back(glm::vec3(0.1f * float(k + 1), 0.05f * float(k + 1), 1.0f));
    return std::make_shared<const LightCookie>(cookie);
}

Light spot(glm::vec3 position, glm::vec3 direction, std::shared_ptr<const LightCookie> cookie) {
    Light light;
    light.type = LightType::Spot;
    light.position = position, light.direction = direction, light.coneAngleDeg = 45.0f;   // tan = 1
    light.intensity = glm::vec3(50.0f, 40.0f, 30.0f);
    light.cookie = std::move(cookie);
    return light;
}

struct Expected {
    glm::vec3 point;
    double u, v;
    int texel;   // row * 4 + column
};

}  // namespace

TEST_CASE("light cookie: a spot aimed straight down has right = +X, up = -Z, u and v spanning the cone") {
    const Light light = spot({0, 5, 0}, {0, -1, 0}, numberedCookie());
    // On the ground 5 m below: u = 0.5 + x / 10, v = 0.5 - z / 10.
    for (const Expected& e : {Expected{{-3, 0, -2}, 0.2, 0.7, 0}, Expected{{4, 0, 1}, 0.9, 0.4, 7},
                              Expected{{1, 0, 3}, 0.6, 0.2, 6}, Expected{{-1, 0, 4}, 0.4, 0.1, 5}}) {
        INFO("point " << e.point.x << ", " << e.point.z);
        const glm::dvec2 uv = cookieCoordinates(light, e.point);
        CHECK(uv.x == doctest::Approx(e.u).epsilon(1e-12));
        CHECK(uv.y == doctest::Approx(e.v).epsilon(1e-12));
        CHECK(cookieTransmission(light, e.point) == light.cookie->texels[size_t(e.texel)]);
    }
}

TEST_CASE("light cookie: a horizontal spot keeps the image's up along +Y, its right along d x Y") {
    const Light light = spot({0, 0, 0}, {1, 0, 0}, numberedCookie());
    // Looking along +X: right = +Z, up = +Y; at 2 m, u = 0.5 + z / 4, v = 0.5 + y / 4.
    const glm::dvec2 uv = cookieCoordinates(light, {2, 1.2f, -1.4f});
    CHECK(uv.x == doctest::Approx(0.15).epsilon(1e-6));
    CHECK(uv.y == doctest::Approx(0.8).epsilon(1e-6));
    CHECK(cookieTransmission(light, {2, 1.2f, -1.4f}) == light.cookie->texels[0]);
    CHECK(cookieTransmission(light, {2, -1.5f, 1.5f}) == light.cookie->texels[7]);
}

TEST_CASE("light cookie: the arrival is the uncookied one times the texel, and nothing outside the cone") {
    const Light plain = spot({0, 5, 0}, {0, -1, 0}, nullptr), cookied = spot({0, 5, 0}, {0, -1, 0}, numberedCookie());
    for (const glm::vec3 point : {glm::vec3(-3, 0, -2), glm::vec3(4, 0, 1), glm::vec3(0.25f, 1, 0.5f)}) {
        const LightArrival a = lightArrival(plain, point), b = lightArrival(cookied, point);
        CHECK(b.toLight == a.toLight);
        CHECK(b.irradiance == a.irradiance * cookieTransmission(cookied, point));
    }
    CHECK(lightArrival(cookied, {6, 0, 0}).irradiance == glm::vec3(0.0f));   // 50 degrees off the axis
    CHECK(cookieTransmission(plain, {1, 0, 1}) == glm::vec3(1.0f));
}
