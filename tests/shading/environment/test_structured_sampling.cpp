// Structured importance sampling (structured_sampling.h): N lights whose Voronoi regions
// tile the sphere and whose powers are the map's integral, the sun sampled first, bright
// strata sampled densely, the same bits for any thread count, bad counts refused.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include <tbb/global_control.h>

#include "shading/environment/structured_sampling.h"
#include "tests/shading/environment/sunny_map.h"

using namespace shadowlab;

TEST_CASE("structured sampling: N lights, regions that tile the sphere, powers that sum to the map's integral") {
    const EnvironmentMap map = sunnyMap(256, 128);
    const glm::dvec3 power = environmentPower(map);
    for (int n : {1, 2, 15, 40, 100, 1000, 4000}) {
        INFO(n);
        std::vector<uint32_t> regions;
        const std::vector<EnvironmentLight> lights = structuredLights(map, buildPyramid(map), n, &regions);
        REQUIRE(int(lights.size()) == n);
        glm::dvec3 sum(0.0);
        double solidAngle = 0.0;
        std::vector<double> regionSolidAngle(lights.size(), 0.0);
        for (const EnvironmentLight& l : lights) {
            sum += l.power, solidAngle += l.solidAngle;
            CHECK(l.solidAngle > 0.0);
            CHECK(std::abs(glm::length(l.direction) - 1.0) < 1e-12);
        }
        for (int j = 0; j < map.height; ++j) {
            for (int i = 0; i < map.width; ++i) regionSolidAngle[regions[size_t(j) * map.width + i]] += map.texelSolidAngle(j);
        }
        for (size_t l = 0; l < lights.size(); ++l) CHECK(regionSolidAngle[l] == doctest::Approx(lights[l].solidAngle).epsilon(1e-9));
        CHECK(solidAngle == doctest::Approx(4.0 * std::numbers::pi).epsilon(1e-12));
        for (int c = 0; c < 3; ++c) CHECK(sum[c] == doctest::Approx(power[c]).epsilon(1e-12));
    }
}

TEST_CASE("structured sampling: the sun is sampled first, and a bright stratum densely") {
    const EnvironmentMap sunny = sunnyMap(256, 128);
    const glm::ivec2 sun = sunny.texelToward(structuredLights(sunny, buildPyramid(sunny), 40)[0].direction);
    CHECK(sunny.at(sun.x, sun.y).r > 1000.0f);
    // A sky of 1 over a ground of 0.1: sigma = 0.45, so the sky is stratum 2 and the ground
    // stratum 0, of equal solid angle; importance Y dOmega^(1/4) gives the sky 10 parts in
    // 11 of the samples (the sun's map puts everything but the sun in stratum 0, and its
    // sky and ground share the rest evenly, spread by area).
    EnvironmentMap halves = constantEnvironment(128, 64, glm::vec3(0.1f));
    for (size_t k = 0; k < halves.radiance.size() / 2; ++k) halves.radiance[k] = glm::vec3(1.0f);
    int sky = 0;
    for (const EnvironmentLight& l : structuredLights(halves, buildPyramid(halves), 44)) sky += l.direction.y > 0.0;
    CHECK(sky == 40);
}

TEST_CASE("structured sampling: the same lights for 1 and 2 threads, and counts outside 1..texels refused") {
    const EnvironmentMap map = sunnyMap(128, 64);
    std::vector<EnvironmentLight> one, two;
    {
        const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
        one = structuredLights(map, buildPyramid(map), 100);
    }
    {
        const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
        two = structuredLights(map, buildPyramid(map), 100);
    }
    REQUIRE(one.size() == two.size());
    for (size_t l = 0; l < one.size(); ++l) {
        CHECK(one[l].direction == two[l].direction);
        CHECK(one[l].power == two[l].power);
    }
    CHECK_THROWS_AS(structuredLights(map, buildPyramid(map), 0), std::invalid_argument);
    CHECK_THROWS_AS(structuredLights(map, buildPyramid(map), 128 * 64 + 1), std::invalid_argument);
    CHECK(structuredLights(map, buildPyramid(map), 128 * 64).size() == size_t(128 * 64));
}
