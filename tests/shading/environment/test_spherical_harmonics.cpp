// Spherical-harmonic irradiance (shading/environment/spherical_harmonics.h) against analytic
// answers: a constant environment gives E = pi L; one bright texel projects to the integrals
// of the basis over its region (checked by quadrature); the basis is orthonormal; E equals
// brute-force integration against the clamped cosine's first three bands on any map; and on
// a map without a sun nine coefficients are within the error Ramamoorthi and Hanrahan state.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>

#include "raster/portable_constants.h"
#include "raster/thread_count.h"
#include "shading/environment/environment_file.h"
#include "shading/environment/spherical_harmonics.h"

#include "sphere_directions.h"
#include "tests/shading/environment/shipped_maps.h"

using namespace shadowlab;

namespace {

// The integral over texel (i, j) of f(direction), by a midpoint rule in (theta, phi) with
// n x n points, each weighted by sin(theta) dtheta dphi.
template <class F>
double quadrature(const EnvironmentMap& map, int i, int j, int n, F f) {
    const double theta0 = map.rowEdgeTheta(j), theta1 = map.rowEdgeTheta(j + 1);
    const double phi0 = map.columnEdgePhi(i), phi1 = map.columnEdgePhi(i + 1);
    double sum = 0.0;
    for (int a = 0; a < n; ++a) {
        const double theta = theta0 + (a + 0.5) * (theta1 - theta0) / n;
        for (int b = 0; b < n; ++b) {
            const double phi = phi0 + (b + 0.5) * (phi1 - phi0) / n;
            const glm::dvec3 d(std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi));
            sum += f(d) * std::sin(theta);
        }
    }
    return sum * (theta1 - theta0) / n * (phi1 - phi0) / n;
}

}  // namespace

TEST_CASE("spherical harmonics: the nine basis functions are orthonormal on the sphere") {
    // Integrated exactly texel by texel over a fine map: the Gram matrix is the identity.
    const EnvironmentMap map = constantEnvironment(256, 128, glm::vec3(1.0f));
    double gram[kShCoefficients][kShCoefficients] = {};
    for (int j = 0; j < map.height; ++j) {
        for (int i = 0; i < map.width; ++i) {
            const std::array<double, kShCoefficients> y = shBasis(map.direction((i + 0.5) / map.width, (j + 0.5) / map.height));
            for (int a = 0; a < kShCoefficients; ++a)
                for (int b = 0; b < kShCoefficients; ++b) gram[a][b] += y[a] * y[b] * map.texelSolidAngle(j);
        }
    }
    for (int a = 0; a < kShCoefficients; ++a) {
        for (int b = 0; b < kShCoefficients; ++b) {
            INFO("Y" << a << " . Y" << b);
            CHECK(std::abs(gram[a][b] - (a == b ? 1.0 : 0.0)) < 1e-3);   // the midpoint rule's error
        }
    }
}

TEST_CASE("spherical harmonics: a constant environment gives L_00 = 2 sqrt(pi) L, nothing else, and E = pi L") {
    const glm::vec3 L(0.25f, 1.0f, 3.0f);
    for (double rotation : {0.0, 1.3}) {
        EnvironmentMap map = constantEnvironment(96, 48, L);
        map.rotationRadians = rotation;
        const ShCoefficients radiance = projectRadiance(map);
        CHECK(glm::length(radiance.c[0] - 2.0 * std::sqrt(kPi) * glm::dvec3(L)) < 1e-13);
        for (int k = 1; k < kShCoefficients; ++k) {
            INFO("coefficient " << k);
            CHECK(glm::length(radiance.c[k]) < 1e-13);
        }
        const ShCoefficients irradiance = irradianceOf(radiance);
        for (const glm::dvec3& n : sphereDirections(50)) {
            CHECK(glm::length(evaluateSh(irradiance, n) - kPi * glm::dvec3(L)) < 1e-12);
        }
    }
}

TEST_CASE("spherical harmonics: one bright texel projects to the basis's integrals over its region") {
    EnvironmentMap map = constantEnvironment(16, 8, glm::vec3(0.0f));
    map.rotationRadians = 0.4;
    for (const glm::ivec2 texel : {glm::ivec2(3, 0), glm::ivec2(11, 2), glm::ivec2(0, 5), glm::ivec2(15, 7)}) {
        std::fill(map.radiance.begin(), map.radiance.end(), glm::vec3(0.0f));
        map.radiance[size_t(texel.y) * 16 + size_t(texel.x)] = glm::vec3(10.0f, 20.0f, 40.0f);
        const ShCoefficients radiance = projectRadiance(map);
        for (int k = 0; k < kShCoefficients; ++k) {
            const double expected = quadrature(map, texel.x, texel.y, 200, [k](const glm::dvec3& d) { return shBasis(d)[k]; });
            INFO("texel " << texel.x << ", " << texel.y << ", coefficient " << k);
            // The midpoint rule with 200^2 points is good to about 1e-5 of the texel's integral of |Y|.
            CHECK(std::abs(radiance.c[k].x - 10.0 * expected) < 1e-5 * 10.0 * map.texelSolidAngle(texel.y));
            CHECK(radiance.c[k].z == doctest::Approx(4.0 * radiance.c[k].x).epsilon(1e-6));
        }
    }
}

// Per normal, the sum over texels of the luminance times kernel(n . d) at the texel's centre
// times its solid angle: the brute-force integral of the map against the kernel.
template <class Kernel>
std::vector<double> bruteForce(const EnvironmentMap& map, const std::vector<glm::dvec3>& normals, Kernel kernel) {
    std::vector<double> sum(normals.size(), 0.0);
    for (int j = 0; j < map.height; ++j) {
        for (int i = 0; i < map.width; ++i) {
            const glm::dvec3 d = map.direction((i + 0.5) / map.width, (j + 0.5) / map.height);
            const double weight = luminance(glm::dvec3(map.at(i, j))) * map.texelSolidAngle(j);
            for (size_t n = 0; n < normals.size(); ++n) sum[n] += weight * kernel(glm::dot(normals[n], d));
        }
    }
    return sum;
}

TEST_CASE("spherical harmonics: E is the map integrated against the clamped cosine's first three bands") {
    // Funk-Hecke: E(n) = integral of L(w) K(n . w) dw with K the clamped cosine's bands 0 to 2,
    // sum_l A_l (2l + 1) / (4 pi) P_l(t) = 1/4 + t/2 + (5/32)(3 t^2 - 1). Brute force with that
    // kernel differs from the nine coefficients only by the midpoint rule, whatever the map
    // (a sun included), so this holds the basis, its constants and the rotation together.
    const auto band2 = [](double t) { return 0.25 + 0.5 * t + (5.0 / 32.0) * (3.0 * t * t - 1.0); };
    for (const char* name : {"blender_interior.exr", "pmndrs_sky.exr"}) {
        const EnvironmentMap map = readEnvironmentMap(kMaps / name, 2.1);
        const ShCoefficients irradiance = irradianceOf(projectRadiance(map));
        const std::vector<glm::dvec3> normals = sphereDirections(40);
        const std::vector<double> expected = bruteForce(map, normals, band2);
        double mean = 0.0, worst = 0.0;
        for (size_t n = 0; n < normals.size(); ++n) {
            mean += expected[n] / normals.size();
            worst = std::max(worst, std::abs(luminance(evaluateSh(irradiance, normals[n])) - expected[n]));
        }
        INFO(name << ": worst difference " << worst / mean << " of the mean E");
        CHECK(worst < 1e-4 * mean);
    }
}

TEST_CASE("spherical harmonics: on a map without a sun nine coefficients are within the paper's error of the exact irradiance") {
    // Ramamoorthi and Hanrahan: an average error of about 1% (at most 5%) on their maps, and
    // at most 9% in theory under their assumptions about the lighting, against the mean
    // irradiance. blender_forest (sky through trees, no sun) meets the average under 3% and
    // the maximum under 9%. Maps with a sun or bright lamps do not (a point source puts the
    // clamped cosine's higher bands, which nine coefficients drop, into E): the interior with
    // its lamps and pmndrs_sky are measured and reported (docs/environment-lighting.md).
    const std::vector<glm::dvec3> normals = sphereDirections(64);
    const auto clampedCosine = [](double t) { return std::max(0.0, t); };
    for (const char* name : {"blender_forest.exr", "blender_interior.exr", "pmndrs_sky.exr"}) {
        const EnvironmentMap map = readEnvironmentMap(kMaps / name);
        const ShCoefficients irradiance = irradianceOf(projectRadiance(map));
        const std::vector<double> exact = bruteForce(map, normals, clampedCosine);
        double mean = 0.0, meanError = 0.0, maxError = 0.0;
        for (size_t n = 0; n < normals.size(); ++n) {
            const double error = std::abs(luminance(evaluateSh(irradiance, normals[n])) - exact[n]);
            mean += exact[n] / normals.size(), meanError += error / normals.size(), maxError = std::max(maxError, error);
        }
        MESSAGE(name << ": mean error " << meanError / mean << ", max " << maxError / mean << " of the mean E");
        if (std::string(name) == "blender_forest.exr") {
            CHECK(meanError < 0.03 * mean);
            CHECK(maxError < 0.09 * mean);
        }
    }
}

TEST_CASE("spherical harmonics: the window damps bands 1 and 2 as sinc^4 and refuses widths that are not windows") {
    ShCoefficients radiance;
    for (int k = 0; k < kShCoefficients; ++k) radiance.c[k] = glm::dvec3(1.0);
    const ShCoefficients plain = irradianceOf(radiance), windowed = irradianceOf(radiance, 6.0);
    const double s1 = std::pow(std::sin(kPi / 6.0) / (kPi / 6.0), 4.0), s2 = std::pow(std::sin(kPi / 3.0) / (kPi / 3.0), 4.0);
    CHECK(windowed.c[0].x == plain.c[0].x);
    CHECK(windowed.c[0].x == doctest::Approx(kPi));
    CHECK(windowed.c[2].x == doctest::Approx(2.0 * kPi / 3.0 * s1));
    CHECK(windowed.c[6].x == doctest::Approx(kPi / 4.0 * s2));
    CHECK_THROWS_AS(irradianceOf(radiance, 1.5), std::invalid_argument);
    CHECK_THROWS_AS(irradianceOf(radiance, -3.0), std::invalid_argument);
    CHECK_THROWS_AS(irradianceOf(radiance, std::nan("")), std::invalid_argument);
}

TEST_CASE("spherical harmonics: the projection is the same bits for 1 and 2 threads") {
    const EnvironmentMap map = readEnvironmentMap(kMaps / "blender_interior.exr", 0.7);
    const ShCoefficients one = withThreads(1, [&] { return projectRadiance(map); });
    const ShCoefficients two = withThreads(2, [&] { return projectRadiance(map); });
    for (int k = 0; k < kShCoefficients; ++k) CHECK(one.c[k] == two.c[k]);
}
