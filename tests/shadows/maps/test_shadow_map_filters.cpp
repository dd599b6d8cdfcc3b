// PCF kernels over a straight shadow edge (RTR 7.5): each returns exactly the cumulative
// weight of its taps that fall on the lit side.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "shadows/maps/pcf.h"

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

MapReceiver receiverAt(double u) {
    MapReceiver r;
    r.texel = glm::dvec2(u, 12.3);
    r.depth = 0.5;
    return r;
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

TEST_CASE("PCF over a straight edge equals the kernel's cumulative weights") {
    const DepthMap map = edgeMap();
    for (double u = 10.0; u <= 22.0; u += 0.0625 + 1.0 / 1024.0) {
        const MapReceiver r = receiverAt(u);
        INFO("u = " << u);
        CHECK(filteredVisibility(map, r, makePcfKernel({FilterKind::Nearest}), 0) == litSide(u));
        // Bilinear: the lit texel centre's weight rises linearly from u = edge - 0.5 to edge + 0.5.
        CHECK(filteredVisibility(map, r, makePcfKernel({FilterKind::Bilinear}), 0) ==
              doctest::Approx(std::clamp(u - (kEdge - 0.5), 0.0, 1.0)).epsilon(1e-12));
        for (int n : {2, 3, 4, 5}) {
            double lit = 0.0;
            for (int a = 0; a < n; ++a) lit += litSide(u - 0.5 * (n - 1) + a);
            FilterSettings grid{FilterKind::Grid};
            grid.gridSize = n;
            CHECK(filteredVisibility(map, r, makePcfKernel(grid), 0) == doctest::Approx(lit / n).epsilon(1e-12));
        }
        FilterSettings poisson{FilterKind::Poisson};
        const PcfKernel kernel = makePcfKernel(poisson);
        for (uint64_t pixel : {0ull, 1ull, 77ull, 123456789ull}) {
            const double angle = poissonRotation(pixel);
            double lit = 0.0;
            for (const glm::dvec2& d : kernel.disk) {
                lit += litSide(u + poisson.poissonRadiusTexels * (std::cos(angle) * d.x - std::sin(angle) * d.y));
            }
            CHECK(filteredVisibility(map, r, kernel, pixel) == doctest::Approx(lit / kernel.disk.size()).epsilon(1e-12));
        }
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
