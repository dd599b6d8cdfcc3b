// The pieces of area-light sampling: PCG32 output, the concentric map, light frames, the
// batched points of a stratified sampling against one point at a time, and a sun's cap of
// directions (equal-area, inside the cap).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "shading/light_sampling.h"
#include "shading/lights.h"

using namespace shadowlab;

TEST_CASE("PCG32 reproduces the reference generator's first outputs") {
    // pcg32-demo of pcg-c-basic: seed 42, sequence 54.
    Pcg32 rng(42u, 54u);
    const uint32_t expected[] = {0xa15c02b7u, 0x7b47f409u, 0xba1d3330u, 0x83d2f293u, 0xbfa4784bu, 0xcbed606eu};
    for (uint32_t e : expected) {
        CHECK(rng.next() == e);
    }
}

TEST_CASE("concentric map sends the square's centre, edges and corners to the disk's") {
    CHECK(concentricSquareToDisk({0.5, 0.5}) == glm::dvec2(0.0));
    const glm::dvec2 right = concentricSquareToDisk({1.0, 0.5});
    CHECK(right.x == doctest::Approx(1.0));
    CHECK(right.y == doctest::Approx(0.0));
    const glm::dvec2 top = concentricSquareToDisk({0.5, 1.0});
    CHECK(top.x == doctest::Approx(0.0));
    CHECK(top.y == doctest::Approx(1.0));
    const glm::dvec2 corner = concentricSquareToDisk({1.0, 1.0});
    CHECK(corner.x == doctest::Approx(std::sqrt(0.5)));
    CHECK(corner.y == doctest::Approx(std::sqrt(0.5)));
    // Concentric squares go to circles: radius = max(|2u-1|, |2v-1|).
    const glm::dvec2 inside = concentricSquareToDisk({0.8, 0.35});
    CHECK(glm::length(inside) == doctest::Approx(0.6));
}

TEST_CASE("the concentric map preserves area: radially and in angle") {
    // A uniform grid on the square must land uniformly on the disk: the disk of radius 1/2
    // and the sector of angles [0, pi/8) each hold their share of the area (1/4, 1/16),
    // up to the grid's discretisation, O(1/n).
    const int n = 400;
    int inCentralDisk = 0, inSector = 0;
    for (int b = 0; b < n; ++b) {
        for (int a = 0; a < n; ++a) {
            const glm::dvec2 d = concentricSquareToDisk({(a + 0.5) / n, (b + 0.5) / n});
            inCentralDisk += glm::length(d) < 0.5;
            const double angle = std::atan2(d.y, d.x);
            inSector += angle >= 0.0 && angle < std::numbers::pi / 8.0;
        }
    }
    CHECK(double(inCentralDisk) / (n * n) == doctest::Approx(1.0 / 4.0).epsilon(0.01));
    CHECK(double(inSector) / (n * n) == doctest::Approx(1.0 / 16.0).epsilon(0.01));
}

TEST_CASE("area light frames span the light") {
    Light rectangle;
    rectangle.type = LightType::Rectangle;
    rectangle.position = {1.0f, 2.0f, 3.0f};
    rectangle.halfEdgeU = {0.5f, 0.0f, 0.0f};
    rectangle.halfEdgeV = {0.0f, 0.0f, 0.25f};
    const AreaLightFrame r = areaLightFrame(rectangle);
    CHECK(areaLightPoint(r, {0.0, 0.0}) == glm::dvec3(0.5, 2.0, 2.75));
    CHECK(areaLightPoint(r, {0.5, 0.5}) == glm::dvec3(1.0, 2.0, 3.0));

    Light disk;
    disk.type = LightType::Disk;
    disk.position = {0.0f, 4.0f, 0.0f};
    disk.direction = {0.3f, -1.0f, 0.2f};
    disk.radius = 0.5f;
    const AreaLightFrame d = areaLightFrame(disk);
    const glm::dvec3 n = areaLightNormal(disk);
    CHECK(glm::length(d.axisA) == doctest::Approx(0.5));
    CHECK(glm::length(d.axisB) == doctest::Approx(0.5));
    CHECK(glm::dot(d.axisA, d.axisB) == doctest::Approx(0.0));
    CHECK(glm::dot(d.axisA, n) == doctest::Approx(0.0));
    CHECK(glm::dot(d.axisB, n) == doctest::Approx(0.0));
    Pcg32 rng(1, 2);
    for (int k = 0; k < 100; ++k) {
        const glm::dvec3 p = areaLightPoint(d, jitteredSample(k % 10, k / 10, 10, rng)) - d.centre;
        CHECK(glm::dot(p, n) == doctest::Approx(0.0));
        CHECK(glm::length(p) <= 0.5 + 1e-12);
    }
    CHECK_THROWS(areaLightFrame(Light{}));
}

TEST_CASE("sobol02: every block of 2^m points puts one point in each elementary rectangle of area 2^-m") {
    for (int m = 0; m <= 8; ++m) {
        const uint32_t n = 1u << m;
        for (uint32_t block = 0; block < 3; ++block) {
            for (int a = 0; a <= m; ++a) {   // rectangles 2^-a wide and 2^-(m - a) high
                std::vector<int> count(n, 0);
                for (uint32_t k = block * n; k < (block + 1) * n; ++k) {
                    const glm::dvec2 p = sobol02(k);
                    REQUIRE(p.x >= 0.0);
                    REQUIRE(p.y < 1.0);
                    ++count[(uint32_t(p.x * (1u << a)) << (m - a)) | uint32_t(p.y * (1u << (m - a)))];
                }
                CHECK(std::count(count.begin(), count.end(), 1) == int(n));
            }
        }
    }
    // Shifted, the points stay in [0, 1).
    for (uint32_t k = 0; k < 64; ++k) {
        const glm::dvec2 p = shiftedSobol02(k, {0.999999999767169356, 0.5});
        CHECK((p.x >= 0.0 && p.x < 1.0 && p.y >= 0.0 && p.y < 1.0));
    }
}

TEST_CASE("AreaLightPoints: the bits and the draws of areaLightPoint of each jittered stratum, disk and rectangle") {
    const Light disk{.type = LightType::Disk, .position = {0.3f, 4.0f, -1.2f}, .direction = glm::normalize(glm::vec3(0.2f, -1.0f, 0.1f)), .radius = 0.7f};
    const Light rectangle{.type = LightType::Rectangle, .position = {-2.0f, 3.0f, 0.5f}, .halfEdgeU = {0.6f, 0.0f, 0.1f}, .halfEdgeV = {0.0f, 0.2f, 0.4f}};
    AreaLightPoints batch;   // reused across lights and sizes, as the reference does
    for (const Light& light : {disk, rectangle, disk}) {
        const AreaLightFrame frame = areaLightFrame(light);
        for (int n : {1, 2, 7, 32}) {
            Pcg32 batched(9u, uint64_t(n)), alone(9u, uint64_t(n));
            batch.fill(frame, n, batched);
            REQUIRE(batch.points().size() == size_t(n * n));
            bool same = true;
            for (int b = 0; b < n; ++b) {
                for (int a = 0; a < n; ++a) {
                    const glm::dvec3 p = areaLightPoint(frame, jitteredSample(a, b, n, alone));
                    same = same && std::memcmp(&p, &batch.points()[size_t(a + n * b)], sizeof p) == 0;
                }
            }
            CHECK(same);
            CHECK(batched.next() == alone.next());   // as many draws
        }
    }
}

TEST_CASE("sunCap: a sun's cap needs a directional light with a size, and keeps the digits of a small one") {
    Light sun{.type = LightType::Directional, .direction = {0.0f, 2.0f, 0.0f}};
    CHECK_THROWS_AS(sunCap(sun), std::invalid_argument);   // size 0: a point-like sun
    CHECK_THROWS_AS(sunCap(Light{.type = LightType::Disk, .radius = 1.0f}), std::invalid_argument);
    sun.angularDiameterDeg = 0.53f;   // the real sun
    const SunCap cap = sunCap(sun);
    CHECK(cap.axis == glm::dvec3(0.0, 1.0, 0.0));
    const double thetaMax = 0.5 * double(sun.angularDiameterDeg) * std::numbers::pi / 180.0;
    // 1 - cos x = x^2/2 - x^4/24 + ..., the next term below 1e-9 of it.
    CHECK(cap.oneMinusCosMax == doctest::Approx(thetaMax * thetaMax / 2.0 - std::pow(thetaMax, 4) / 24.0).epsilon(1e-12));
    CHECK(std::abs(glm::dot(cap.axis, cap.tangentA)) < 1e-15);
    CHECK(std::abs(glm::dot(cap.axis, cap.tangentB)) < 1e-15);
    CHECK(glm::cross(cap.tangentA, cap.tangentB) == glm::dvec3(0.0, 1.0, 0.0));
}

// Uniform in solid angle over the cap of half-angle theta_max, cos theta is uniform on
// [cos theta_max, 1]: its mean is (1 + cos theta_max) / 2, standard deviation h / sqrt(12)
// with h = 1 - cos theta_max, and each quarter of [cos theta_max, 1] and each quadrant of
// azimuth holds a quarter of the directions. N independent samples miss the mean by less
// than 5 h / sqrt(12 N) except with probability below 1e-6 (stratified ones by less); a map
// that is not equal-area, cos theta = 1 - r h (uniform in r), has mean 1 - 2h/3, h/6 away.
TEST_CASE("sunCapDirection: equal-area over the cap and inside it, stratified batch the same bits") {
    AreaLightPoints batch;
    for (float size : {0.53f, 3.0f, 40.0f, 170.0f}) {
        const Light sun{.type = LightType::Directional, .direction = glm::normalize(glm::vec3(0.3f, 1.0f, -0.2f)), .angularDiameterDeg = size};
        const SunCap cap = sunCap(sun);
        const double h = cap.oneMinusCosMax, cosMax = 1.0 - h;
        const int n = 64, count = n * n;
        Pcg32 batched(5u, 77u), alone(5u, 77u);
        batch.fill(cap, n, batched);
        REQUIRE(batch.points().size() == size_t(count));
        double sumCos = 0.0;
        int quarter[4] = {0, 0, 0, 0}, quadrant[4] = {0, 0, 0, 0}, outside = 0, notUnit = 0;
        bool same = true;
        for (int b = 0; b < n; ++b) {
            for (int a = 0; a < n; ++a) {
                const glm::dvec3 d = batch.points()[size_t(a + n * b)];
                const glm::dvec3 one = sunCapDirection(cap, concentricSquareToDisk(jitteredSample(a, b, n, alone)));
                same = same && std::memcmp(&d, &one, sizeof d) == 0;
                const double cosTheta = glm::dot(d, cap.axis);
                sumCos += cosTheta;
                outside += cosTheta < cosMax - 1e-12;
                notUnit += std::abs(glm::length(d) - 1.0) > 1e-12;
                ++quarter[std::min(3, int(4.0 * (1.0 - cosTheta) / h))];
                ++quadrant[(glm::dot(d, cap.tangentA) < 0.0) + 2 * (glm::dot(d, cap.tangentB) < 0.0)];
            }
        }
        CAPTURE(size);
        CHECK(same);
        CHECK(batched.next() == alone.next());   // as many draws
        CHECK(outside == 0);
        CHECK(notUnit == 0);
        CHECK(std::abs(sumCos / count - (1.0 + cosMax) / 2.0) <= 5.0 * h / std::sqrt(12.0 * count));
        for (int k = 0; k < 4; ++k) {
            // Binomial(N, 1/4): standard deviation sqrt(3N)/4 = 28 for N = 4096; five of them.
            CHECK(std::abs(quarter[k] - count / 4) <= 140);
            CHECK(std::abs(quadrant[k] - count / 4) <= 140);
        }
    }
}
