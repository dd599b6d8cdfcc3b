// The source set (differential/source_set.h, Gibson et al. 2003 section 4): the
// shortest run of the brightest patches whose power reaches the share, a light of one
// radiance whole however finely it is cut, nothing that emits nothing, bad input refused.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include "differential/source_set.h"

using namespace shadowlab;

TEST_CASE("source set: the brightest patches, just enough of them to reach the share of the power") {
    // By radiance 10, 5, 1, 0 (patches 1, 3, 0, 2): powers (less pi) 10, 20, 10, 0 of 40.
    const std::vector<EmittingPatch> room{{1.0, 10.0}, {10.0, 1.0}, {0.0, 50.0}, {5.0, 4.0}};
    CHECK(selectSources(room, 0.2) == std::vector<uint32_t>{1});         // 10 of 40 reaches 8
    CHECK(selectSources(room, 0.25) == std::vector<uint32_t>{1});        // exactly reached
    CHECK(selectSources(room, 0.7) == std::vector<uint32_t>{1, 3});      // 30 reaches 28
    CHECK(selectSources(room, 0.75) == std::vector<uint32_t>{1, 3});     // 30 reaches 30
    CHECK(selectSources(room, 0.8) == std::vector<uint32_t>{1, 3, 0});   // 30 < 32: the dim one too
    CHECK(selectSources(room, 1.0) == std::vector<uint32_t>{1, 3, 0});   // never the dark floor
    CHECK(selectSources(std::vector<EmittingPatch>{{0.0, 1.0}}, 1.0).empty());
    CHECK(selectSources({}, 0.7).empty());
}

TEST_CASE("source set: a random room's set is the shortest reaching prefix of the sorted patches") {
    std::mt19937_64 rng(12);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<EmittingPatch> patches;
    for (int p = 0; p < 2000; ++p) {
        const double r = u(rng);
        const double radiance = r < 0.01 ? 100.0 * u(rng) : r < 0.3 ? u(rng) : 0.0;   // lamps, walls, dark
        patches.push_back({radiance, 0.01 + u(rng)});
    }
    double total = 0.0;
    for (const EmittingPatch& e : patches) total += e.radiance * e.area;
    const std::vector<uint32_t> set = selectSources(patches);
    double power = 0.0, last = std::numeric_limits<double>::infinity();
    for (uint32_t p : set) {
        REQUIRE(patches[p].radiance <= last);
        last = patches[p].radiance;
        power += patches[p].radiance * patches[p].area;
    }
    CHECK(power >= 0.7 * total);
    CHECK(power - patches[set.back()].radiance * patches[set.back()].area < 0.7 * total);   // one fewer would not do
    for (size_t p = 0; p < patches.size(); ++p) {   // nothing brighter than the last was left out
        if (patches[p].radiance > last) REQUIRE(std::find(set.begin(), set.end(), uint32_t(p)) != set.end());
    }
}

TEST_CASE("source set: a share of the power that is not above 0 and at most 1, and bad patches, are refused") {
    const std::vector<EmittingPatch> one{{1.0, 1.0}};
    for (double share : {0.0, -0.1, 1.5, std::nan("")}) CHECK_THROWS_AS(selectSources(one, share), std::invalid_argument);
    CHECK_THROWS_AS(selectSources(std::vector<EmittingPatch>{{-1.0, 1.0}}, 0.7), std::invalid_argument);
    CHECK_THROWS_AS(selectSources(std::vector<EmittingPatch>{{1.0, std::nan("")}}, 0.7), std::invalid_argument);
    CHECK_THROWS_AS(selectSources(std::vector<EmittingPatch>{{std::numeric_limits<double>::infinity(), 1.0}}, 0.7),
                    std::invalid_argument);
}

TEST_CASE("source set: a light of one radiance is in the set whole, however finely it is cut") {
    // A window of radiance 7 and 1.68 m^2 beside a panel of 9 and 0.6 m^2 and dim walls of
    // 0.1 and 30 m^2: the panel holds 5.4 of 20.16, so 70% needs part of the window.
    for (const int pieces : {1, 4, 16, 64}) {
        std::vector<EmittingPatch> patches{{9.0, 0.6}};
        for (int k = 0; k < pieces; ++k) patches.push_back({7.0, 1.68 / pieces});
        for (int k = 0; k < 30; ++k) patches.push_back({0.1, 1.0});
        const std::vector<uint32_t> set = selectSources(patches, 0.7);
        const auto inWindow = [&](uint32_t p) { return p >= 1 && int(p) <= pieces; };
        const auto window = std::count_if(set.begin(), set.end(), inWindow);
        INFO(pieces << " pieces");
        CHECK(set.front() == 0);
        CHECK(window == pieces);
        CHECK(set.size() == size_t(pieces) + 1);   // the walls are not needed
    }
}
