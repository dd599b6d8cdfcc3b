// PCF kernels over a straight shadow edge (RTR 7.5): each returns exactly the cumulative
// weight of its taps that fall on the lit side, at every SIMD level.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "raster/tile_kernels.h"
#include "shadows/maps/pcf.h"
#include "shadows/maps/shadow_lookup.h"

using namespace shadowlab;

namespace {

constexpr int kSize = 32, kEdge = 16;   // texels x < kEdge hold an occluder (depth 0), the rest nothing (1)

DepthMap edgeMap() {
    DepthMap map;
    map.size = kSize;
    map.tilesX = 1;
    map.depth.resize(raster::kPixelsPerTile);
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) map.depth[raster::blockLinearIndex(x, y, map.tilesX)] = x < kEdge ? 0.0f : 1.0f;
    }
    return map;
}

double litSide(double u) { return std::floor(u) >= kEdge ? 1.0 : 0.0; }

}  // namespace

TEST_CASE("texelIndexOf is floor, saturated, for every coordinate a lookup can meet") {
    for (double c : {0.0, -0.0, 0.5, 1.0, 1.0 - 1e-12, -1e-300, -0.5, -1.0, -1.0 - 1e-12, 2047.999999, 2048.0, -3.25, 1e6 + 0.5}) {
        INFO("c = " << c);
        CHECK(texelIndexOf(c) == int(std::floor(c)));
    }
    CHECK(texelIndexOf(1e300) == 1 << 30);
    CHECK(texelIndexOf(-1e300) == -(1 << 30));
    CHECK(texelIndexOf(std::numeric_limits<double>::infinity()) == 1 << 30);
    CHECK(texelIndexOf(std::nan("")) == -(1 << 30));
}

TEST_CASE("a depth map reads its block-linear texels in place, clamped, and image() gives the same rows") {
    const DepthMap map = edgeMap();
    const std::vector<float> rows = map.image();
    REQUIRE(rows.size() == size_t(kSize * kSize));
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) REQUIRE(rows[size_t(y) * kSize + size_t(x)] == (x < kEdge ? 0.0f : 1.0f));
    }
    CHECK(map.at(-5, 3) == 0.0f);
    CHECK(map.at(kSize + 7, -2) == 1.0f);
}

TEST_CASE("PCF over a straight edge equals the kernel's cumulative weights, at every SIMD level") {
    // One receiver per lane, u = 10 .. 22 texels across the edge in steps of 65/1024 (exact
    // in float), through the lookup's filter stage (lookup_kernel.h) as the shadow map runs it.
    const DepthMap map = edgeMap();
    std::vector<float> u;
    for (int k = 0; 10.0f + float(k) * (65.0f / 1024.0f) <= 22.0f; ++k) u.push_back(10.0f + float(k) * (65.0f / 1024.0f));
    while (u.size() % 16 != 0) u.push_back(u.back());   // whole vectors at every width
    const int count = int(u.size());
    for (raster::SimdLevel level : {raster::SimdLevel::Scalar, raster::SimdLevel::Avx2, raster::SimdLevel::Avx512}) {
        if (!raster::simdLevelSupported(level)) continue;
        CAPTURE(raster::simdLevelName(level));
        // Nearest, bilinear, N x N grids and the rotated Poisson disk, each against the
        // weight of its taps on the lit side.
        const auto run = [&](const FilterSettings& settings, const auto& expected) {
            const PcfKernel kernel = makePcfKernel(settings);
            std::vector<float> diskX, diskY;
            for (const glm::dvec2& d : kernel.disk) diskX.push_back(float(d.x)), diskY.push_back(float(d.y));
            const LookupMap lookupMap{{}, {}, map.depth.data(), map.size, map.tilesX, nullptr};
            LookupConstants c{};
            c.maps = &lookupMap, c.mapCount = 1, c.gridSize = settings.gridSize;
            c.diskX = diskX.data(), c.diskY = diskY.data(), c.diskTaps = int(diskX.size());
            c.radiusTexels = float(settings.poissonRadiusTexels);
            const size_t n = size_t(count);
            std::vector<uint8_t> served(n, 1);
            std::vector<float> y(n, 12.3f), depth(n, 0.5f), visibility(n), rotationCos, rotationSin;
            for (int k = 0; k < count; ++k) {
                rotationCos.push_back(float(std::cos(poissonRotation(uint64_t(k)))));
                rotationSin.push_back(float(std::sin(poissonRotation(uint64_t(k)))));
            }
            std::vector<float> x = u;
            const LookupRow row{nullptr, nullptr, served.data(), rotationCos.data(), rotationSin.data(),
                                {x.data(), y.data(), depth.data(), nullptr, nullptr, nullptr, nullptr},
                                visibility.data(), nullptr, nullptr, nullptr, nullptr, count};
            lookupKernels(level).filter[int(settings.kind)][0](c, row);
            for (int k = 0; k < count; ++k) {
                CAPTURE(u[size_t(k)]);
                CHECK(visibility[size_t(k)] == doctest::Approx(expected(u[size_t(k)], rotationCos[size_t(k)], rotationSin[size_t(k)],
                                                                        diskX, diskY)).epsilon(1e-6));
            }
        };
        run({FilterKind::Nearest}, [](float x, float, float, const auto&, const auto&) { return litSide(x); });
        // Bilinear: the lit texel centre's weight rises linearly from u = edge - 0.5 to edge + 0.5.
        run({FilterKind::Bilinear},
            [](float x, float, float, const auto&, const auto&) { return std::clamp(x - (kEdge - 0.5), 0.0, 1.0); });
        for (int n : {2, 3, 4, 5}) {
            FilterSettings grid{FilterKind::Grid};
            grid.gridSize = n;
            run(grid, [n](float x, float, float, const auto&, const auto&) {
                double lit = 0.0;
                for (int a = 0; a < n; ++a) lit += litSide(x + (-0.5f * float(n - 1) + float(a)));
                return lit / n;
            });
        }
        FilterSettings poisson{FilterKind::Poisson};
        run(poisson, [&](float x, float cosine, float sine, const std::vector<float>& dx, const std::vector<float>& dy) {
            // The tap's x in float, as the kernel places it (y does not cross the edge).
            double lit = 0.0;
            const float radius = float(poisson.poissonRadiusTexels);
            for (size_t t = 0; t < dx.size(); ++t) lit += litSide(x + radius * (cosine * dx[t] - sine * dy[t]));
            return lit / double(dx.size());
        });
    }
}

TEST_CASE("the Poisson disk is spread out and its rotation is a pure function of the pixel") {
    const PcfKernel kernel = makePcfKernel({FilterKind::Poisson});
    REQUIRE(kernel.disk.size() == 16);
    double closest = 2.0;
    for (size_t a = 0; a < kernel.disk.size(); ++a) {
        CHECK(glm::length(kernel.disk[a]) <= 1.0);
        for (size_t b = 0; b < a; ++b) closest = std::min(closest, glm::length(kernel.disk[a] - kernel.disk[b]));
    }
    // 16 points of a Poisson disk in the unit disk keep about 0.75 / sqrt(16) apart or more.
    CHECK(closest > 0.25);
    CHECK(makePcfKernel({FilterKind::Poisson}).disk == kernel.disk);
    CHECK(poissonRotation(42) == poissonRotation(42));
    CHECK(poissonRotation(42) != poissonRotation(43));
    double mean = 0.0;
    for (uint64_t k = 0; k < 10000; ++k) mean += poissonRotation(k) / (2.0 * M_PI);
    CHECK(mean / 10000.0 == doctest::Approx(0.5).epsilon(0.02));
}
