// Importance sampling of an environment map (environment_distribution.h): the density is
// normalised over the sphere, a sample's stated density is the density of its direction,
// and texels are drawn in proportion to their luminance times solid angle.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "shading/environment/environment_distribution.h"
#include "shading/light_sampling.h"
#include "tests/shading/environment/sunny_map.h"

using namespace shadowlab;

TEST_CASE("environment distribution: the density integrates to 1 over the sphere, as the texels' sum") {
    const EnvironmentMap map = sunnyMap(64, 32);
    const EnvironmentDistribution distribution(map);
    REQUIRE_FALSE(distribution.empty());
    double integral = 0.0;
    for (int j = 0; j < map.height; ++j) {
        for (int i = 0; i < map.width; ++i) {
            const glm::dvec3 centre = map.direction((i + 0.5) / map.width, (j + 0.5) / map.height);
            integral += distribution.pdf(centre) * map.texelSolidAngle(j);
        }
    }
    CHECK(integral == doctest::Approx(1.0).epsilon(1e-12));
}

TEST_CASE("environment distribution: samples carry their direction's density and follow the texels' weights") {
    const EnvironmentMap map = sunnyMap(64, 32);
    const EnvironmentDistribution distribution(map);
    Pcg32 rng(7, 3);
    std::vector<double> counts(map.radiance.size(), 0.0);
    const int n = 200000;
    int inSun = 0;
    for (int s = 0; s < n; ++s) {
        const EnvironmentSample e =
            distribution.sample({rng.nextDouble(), rng.nextDouble(), rng.nextDouble(), rng.nextDouble()});
        CHECK(std::abs(glm::length(e.direction) - 1.0) < 1e-12);
        const glm::ivec2 t = map.texelToward(e.direction);
        // A direction on a texel's edge may round into its neighbour; inside, the densities agree.
        if (std::abs(distribution.pdf(e.direction) - e.pdf) > 1e-9 * e.pdf) continue;
        counts[size_t(t.y) * map.width + t.x] += 1.0;
        inSun += luminance(glm::dvec3(map.at(t.x, t.y))) > 1000.0;
    }
    // The sun's four texels hold this share of luminance times solid angle.
    double sun = 0.0, all = 0.0;
    for (int j = 0; j < map.height; ++j) {
        for (int i = 0; i < map.width; ++i) {
            const double w = luminance(glm::dvec3(map.at(i, j))) * map.texelSolidAngle(j);
            all += w, sun += luminance(glm::dvec3(map.at(i, j))) > 1000.0 ? w : 0.0;
        }
    }
    CHECK(double(inSun) / n == doctest::Approx(sun / all).epsilon(0.01));
}

TEST_CASE("environment distribution: a black map has none") {
    const EnvironmentMap black = constantEnvironment(8, 4, glm::vec3(0.0f));
    CHECK(EnvironmentDistribution(black).empty());
}
