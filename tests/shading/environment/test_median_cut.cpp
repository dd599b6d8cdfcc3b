// Median-cut sampling of an environment into lights (shading/environment/median_cut.h): the
// regions tile the map, the lights' powers sum to the map's integral, a light sits where its
// region's energy is, and bad counts are errors.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include "raster/portable_constants.h"
#include "shading/environment/environment_file.h"
#include "shading/environment/median_cut.h"
#include "tests/shading/environment/shipped_maps.h"

using namespace shadowlab;

TEST_CASE("median cut: the regions tile the map and the lights' powers sum to its integral, N from 1 to 4000") {
    const EnvironmentMap map = readEnvironmentMap(kMaps / "blender_interior.exr", 0.3);
    const glm::dvec3 total = environmentPower(map);
    for (int n : {1, 2, 3, 15, 16, 40, 100, 1000, 4000}) {
        const std::vector<EnvironmentLight> lights = medianCutLights(map, n);
        REQUIRE(int(lights.size()) == n);
        std::vector<int> covered(map.radiance.size(), 0);
        glm::dvec3 power(0.0);
        for (const EnvironmentLight& l : lights) {
            power += l.power;
            CHECK(std::abs(glm::length(l.direction) - 1.0) < 1e-12);
            for (int j = l.first.y; j < l.last.y; ++j)
                for (int i = l.first.x; i < l.last.x; ++i) ++covered[size_t(j) * size_t(map.width) + size_t(i)];
        }
        INFO(n << " lights");
        CHECK(std::count(covered.begin(), covered.end(), 1) == std::ptrdiff_t(covered.size()));
        CHECK(glm::length(power - total) < 1e-12 * glm::length(total));
    }
}

TEST_CASE("median cut: regions of about equal energy, the light at its region's energy centroid") {
    // A map dark but for one bright texel: of two lights, one carries all of its power, its
    // direction the texel's centre; a constant map's four lights carry equal energies.
    EnvironmentMap map = constantEnvironment(64, 32, glm::vec3(0.0f));
    map.radiance[size_t(5) * 64 + 40] = glm::vec3(100.0f);
    const std::vector<EnvironmentLight> two = medianCutLights(map, 2);
    const glm::dvec3 centre = map.direction(40.5 / 64.0, 5.5 / 32.0);
    bool found = false;
    for (const EnvironmentLight& l : two) {
        if (glm::length(l.power) > 0.0) {
            found = true;
            CHECK(glm::length(l.direction - centre) < 1e-12);
            CHECK(l.power.x == doctest::Approx(100.0 * map.texelSolidAngle(5)));
        }
    }
    CHECK(found);
    const EnvironmentMap constant = constantEnvironment(64, 32, glm::vec3(1.0f));
    const std::vector<EnvironmentLight> four = medianCutLights(constant, 4);
    for (const EnvironmentLight& l : four) {
        INFO("region " << l.first.x << "," << l.first.y << " .. " << l.last.x << "," << l.last.y);
        CHECK(l.power.x == doctest::Approx(kPi).epsilon(1e-12));   // 4 pi / 4: the halves split exactly
    }
}

TEST_CASE("median cut: cuts follow the energy, not the middle, and the brightest region is cut next") {
    // Two bright texels in one row, at columns 5 and 20 of 64: a cut in the middle (32) would
    // leave both in one half; the energy median puts one in each. The brighter one's region
    // is cut for the third light; the other's stays as it was.
    EnvironmentMap map = constantEnvironment(64, 32, glm::vec3(0.0f));
    map.radiance[size_t(16) * 64 + 5] = glm::vec3(10.0f);
    map.radiance[size_t(16) * 64 + 20] = glm::vec3(1.0f);
    const auto holding = [](const std::vector<EnvironmentLight>& lights, int column) {
        for (const EnvironmentLight& l : lights) {
            if (l.first.x <= column && column < l.last.x && l.first.y <= 16 && 16 < l.last.y) return l;
        }
        FAIL("no region holds the texel");
        return EnvironmentLight{};
    };
    const std::vector<EnvironmentLight> two = medianCutLights(map, 2);
    const EnvironmentLight bright = holding(two, 5), dim = holding(two, 20);
    CHECK(bright.first != dim.first);
    CHECK(bright.power.x == doctest::Approx(10.0 * map.texelSolidAngle(16)));
    CHECK(dim.power.x == doctest::Approx(map.texelSolidAngle(16)));
    const std::vector<EnvironmentLight> three = medianCutLights(map, 3);
    const EnvironmentLight dimAfter = holding(three, 20);
    CHECK(dimAfter.first == dim.first);
    CHECK(dimAfter.last == dim.last);
    CHECK(holding(three, 5).last - holding(three, 5).first != bright.last - bright.first);
}

TEST_CASE("median cut: the same lights on every run, and bad counts are errors") {
    const EnvironmentMap map = readEnvironmentMap(kMaps / "pmndrs_sky.exr");
    const std::vector<EnvironmentLight> a = medianCutLights(map, 64), b = medianCutLights(map, 64);
    for (size_t k = 0; k < a.size(); ++k) {
        CHECK(a[k].direction == b[k].direction);
        CHECK(a[k].power == b[k].power);
    }
    CHECK_THROWS_AS(medianCutLights(map, 0), std::invalid_argument);
    CHECK_THROWS_AS(medianCutLights(map, -3), std::invalid_argument);
    CHECK_THROWS_AS(medianCutLights(constantEnvironment(4, 2, glm::vec3(1.0f)), 9), std::invalid_argument);
    CHECK(medianCutLights(constantEnvironment(4, 2, glm::vec3(1.0f)), 8).size() == 8);   // one light per texel
}
