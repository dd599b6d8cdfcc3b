// The radiance cache (radiance_cache.h): the octahedral map of normals round-trips, a
// constant environment gives each model its directional albedo times L, and on a sunny map
// each texel's integral agrees with brute force over every map texel, Blinn-Phong included.
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>

#include "shading/environment/radiance_cache.h"
#include "shading/shade.h"
#include "tests/shading/environment/sphere_directions.h"
#include "tests/shading/environment/sunny_map.h"

using namespace shadowlab;

namespace {

// Brute force: f cos L dOmega summed at every map texel's centre.
glm::dvec3 bruteForceAtTexelCentres(const EnvironmentMap& map, const Material& m, const glm::dvec3& N, const glm::dvec3& v) {
    glm::dvec3 sum(0.0);
    for (int j = 0; j < map.height; ++j) {
        for (int i = 0; i < map.width; ++i) {
            const glm::dvec3 l = map.direction((i + 0.5) / map.width, (j + 0.5) / map.height);
            const double c = glm::dot(N, l);
            if (c > 0.0) sum += glm::dvec3(brdf(m, m.albedo, glm::vec3(N), glm::vec3(l), glm::vec3(v))) * glm::dvec3(map.at(i, j)) * c * map.texelSolidAngle(j);
        }
    }
    return sum;
}

const Material kBlinn{.name = "blinn", .model = MaterialModel::BlinnPhong, .albedo = glm::vec3(0.3f),
                      .specular = glm::vec3(0.5f), .shininess = 60.0f};

}  // namespace

TEST_CASE("radiance cache: the octahedral map round-trips every direction") {
    for (const glm::dvec3& d : sphereDirections(2000)) {
        const glm::dvec2 uv = octahedralEncode(d);
        CHECK((uv.x >= 0.0 && uv.x <= 1.0 && uv.y >= 0.0 && uv.y <= 1.0));
        CHECK(glm::length(octahedralDecode(uv) - d) < 1e-12);
    }
}

TEST_CASE("radiance cache: a cached normal's integral agrees with brute force over the map, for Lambert and Blinn-Phong") {
    const EnvironmentMap map = sunnyMap(128, 64);
    const EnvironmentPyramid pyramid = buildPyramid(map);
    const glm::dvec3 v = glm::normalize(glm::dvec3(0.2, 0.5, 1.0));
    const Material lambert{.name = "lambert", .albedo = glm::vec3(0.6f)};
    for (const Material* m : {&lambert, &kBlinn}) {
        INFO(m->name);
        const RadianceCache cache = buildRadianceCache(map, pyramid, *m, v, 16);
        double worst = 0.0;
        for (int j = 0; j < cache.size; ++j) {
            for (int i = 0; i < cache.size; ++i) {
                const glm::dvec3 N = octahedralDecode({(i + 0.5) / cache.size, (j + 0.5) / cache.size});
                const glm::dvec3 exact = bruteForceAtTexelCentres(map, *m, N, v);
                const glm::dvec3 cached(cache.radiance[size_t(j) * cache.size + i]);
                if (luminance(exact) > 1e-3) worst = std::max(worst, std::abs(luminance(cached) / luminance(exact) - 1.0));
            }
        }
        MESSAGE(m->name << ": worst relative difference " << worst);
        CHECK(worst < 0.02);
    }
}

TEST_CASE("radiance cache: lookups between texels interpolate, and the size is checked") {
    const EnvironmentMap map = constantEnvironment(64, 32, glm::vec3(2.0f));
    const EnvironmentPyramid pyramid = buildPyramid(map);
    const Material lambert{.name = "lambert", .albedo = glm::vec3(0.5f)};
    const RadianceCache cache = buildRadianceCache(map, pyramid, lambert, {0.0, 0.0, 1.0}, 32);
    // A constant sky over a Lambert surface: albedo L for every normal, to the midpoint rule's error.
    for (const glm::dvec3& N : sphereDirections(200)) CHECK(lookupRadianceCache(cache, N).r == doctest::Approx(1.0).epsilon(5e-3));
    // Lookups read the texel at its centre and the mean of two neighbours halfway between
    // them (a half-texel shift or swapped weights fail both), on a map where C varies.
    EnvironmentMap halves = constantEnvironment(64, 32, glm::vec3(0.1f));
    for (size_t k = 0; k < halves.radiance.size() / 2; ++k) halves.radiance[k] = glm::vec3(1.0f);
    const RadianceCache varied = buildRadianceCache(halves, buildPyramid(halves), lambert, {0.0, 0.0, 1.0}, 16);
    const auto texel = [&](int i, int j) { return double(varied.radiance[size_t(j) * 16 + size_t(i)].r); };
    for (int j = 1; j < 15; j += 3) {
        for (int i = 1; i < 14; i += 3) {
            const double centre = lookupRadianceCache(varied, octahedralDecode({(i + 0.5) / 16, (j + 0.5) / 16})).r;
            const double between = lookupRadianceCache(varied, octahedralDecode({(i + 1.0) / 16, (j + 0.5) / 16})).r;
            CHECK(centre == doctest::Approx(texel(i, j)).epsilon(1e-6));
            CHECK(between == doctest::Approx(0.5 * (texel(i, j) + texel(i + 1, j))).epsilon(1e-6));
        }
    }
    CHECK_THROWS_AS(buildRadianceCache(map, pyramid, lambert, {0.0, 0.0, 1.0}, 1), std::invalid_argument);
}
