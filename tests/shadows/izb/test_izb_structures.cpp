// The irregular z-buffer's building blocks: the counting-sort lists equal a naive
// construction, and the conservative footprint of an occluder misses no texel where a
// brute-force exact test finds a receiver it shadows.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstring>
#include <functional>
#include <numeric>
#include <random>
#include <string>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>

#include "frame/render.h"
#include "scenes/scene_file.h"
#include "shadows/izb/izb.h"
#include "shadows/reference/reference.h"

using namespace shadowlab;

TEST_CASE("izb texel lists equal lists built by appending receivers in pixel order") {
    const Scene scene = loadScene("sphere-box");
    const WorldGeometry world = flatten(scene);
    const GBuffer g = renderGBuffer(world, scene.camera, raster::bestSimdLevel());
    const Light light = pointLightFor(scene.lights[0]);
    std::vector<float> V;
    const izb::Receivers receivers = izb::gatherReceivers(g, light, sceneDiagonal(world), V, raster::bestSimdLevel());
    const izb::LightGrid grid = izb::makeLightGrid(izb::fitViews(light, g, world, raster::bestSimdLevel()), 300, sceneDiagonal(world));
    const auto texel = izb::receiverTexels(grid.resolution, izb::placeReceivers(grid.views, receivers));
    const izb::TexelLists lists = izb::buildTexelLists(texel, grid.texelCount());

    std::vector<std::vector<uint32_t>> naive(grid.texelCount());
    for (uint32_t r = 0; r < receivers.size(); ++r) naive[izb::texelOf(grid, glm::dvec3(receivers[r].origin))].push_back(r);
    size_t mismatches = 0;
    for (size_t t = 0; t < grid.texelCount(); ++t) {
        const std::vector<uint32_t> built(lists.entry.begin() + lists.first[t], lists.entry.begin() + lists.first[t + 1]);
        mismatches += built != naive[t];
    }
    CHECK(mismatches == 0);
    CHECK(lists.entry.size() == receivers.size());
    // Receivers are the hit pixels facing the light, in pixel order.
    CHECK(std::adjacent_find(receivers.begin(), receivers.end(), [](const izb::Receiver& a, const izb::Receiver& b) {
              return a.pixel >= b.pixel;
          }) == receivers.end());
}

TEST_CASE("izb texel numbers: one per texel, below texelCount, a tile's and a tile row's consecutive") {
    for (const int R : {16, 32, 33, 100}) {
        CAPTURE(R);
        izb::LightGrid grid;
        grid.views.resize(2);
        grid.resolution = R;
        std::vector<uint8_t> seen(grid.texelCount(), 0);
        size_t repeats = 0, outOfRow = 0;
        for (int view = 0; view < 2; ++view) {
            for (int j = 0; j < R; ++j) {
                for (int i = 0; i < R; ++i) {
                    const size_t t = grid.texelIndex(view, i, j);
                    REQUIRE(t < grid.texelCount());
                    repeats += seen[t]++;
                    // Inside a tile, the next texel of a row is the next number.
                    if (i % izb::kTileSize != 0) outOfRow += t != grid.texelIndex(view, i - 1, j) + 1;
                }
            }
        }
        CHECK(repeats == 0);
        CHECK(outOfRow == 0);
        const size_t tilesPerView = size_t(izb::tilesPerSide(R)) * size_t(izb::tilesPerSide(R));
        // Tiles follow each other in row order, views after all of the previous view's tiles.
        constexpr size_t kPerTile = size_t(izb::kTileSize) * izb::kTileSize;
        if (R > izb::kTileSize) {
            CHECK(grid.texelIndex(0, izb::kTileSize, 0) == kPerTile);
            CHECK(grid.texelIndex(0, 0, izb::kTileSize) == size_t(izb::tilesPerSide(R)) * kPerTile);
        }
        CHECK(grid.texelIndex(1, 0, 0) == tilesPerView * kPerTile);
    }
}

TEST_CASE("izb counting sort keeps values in order within each key") {
    // One group of keys in one chunk of items, and many of both (lists.cpp sorts by groups
    // of 1024 keys, chunks of 16384 items in parallel): the buckets are a stable sort's.
    for (const std::pair<uint32_t, size_t>& size : {std::pair<uint32_t, size_t>{97, 5000}, std::pair<uint32_t, size_t>{5000, 100000}}) {
        const uint32_t keyCount = size.first;
        const size_t items = size.second;
        std::mt19937 rng(7);
        std::vector<uint32_t> key(items), value(items);
        for (size_t k = 0; k < key.size(); ++k) key[k] = rng() % keyCount, value[k] = rng();
        const izb::Buckets b = izb::countingSort(key, keyCount, value);
        std::vector<uint32_t> order(items);
        std::iota(order.begin(), order.end(), 0u);
        std::stable_sort(order.begin(), order.end(), [&](uint32_t i, uint32_t j) { return key[i] < key[j]; });
        std::vector<uint32_t> expected(items);
        for (size_t e = 0; e < items; ++e) expected[e] = value[order[e]];
        CHECK(std::equal(b.entry.begin(), b.entry.end(), expected.begin(), expected.end()));
        REQUIRE(b.first.size() == keyCount + 1);
        bool offsetsRight = true;
        for (uint32_t bucket = 0; bucket <= keyCount; ++bucket) {
            const size_t before = size_t(std::lower_bound(order.begin(), order.end(), bucket,
                                                          [&](uint32_t i, uint32_t k) { return key[i] < k; }) -
                                         order.begin());
            offsetsRight = offsetsRight && b.first[bucket] == before;
        }
        CHECK(offsetsRight);
    }
}

namespace {

// A 16 x 16 grid of one light view, and receivers spread over it, a fifth of them exactly on
// texel edges or corners (the cases a conservative footprint must not lose).
struct SmallCase {
    izb::LightGrid grid;
    izb::HomogeneousLight light;
    std::vector<glm::dvec3> receivers;
};

SmallCase smallCase(bool orthographic, std::mt19937& rng) {
    SmallCase c;
    const int R = 16;
    const glm::dvec3 eye(0.3, 5.0, 0.2), target(0.0, 0.0, 0.0);
    LightView view;
    view.orthographic = orthographic;
    view.viewFromWorld = glm::lookAtRH(eye, target, glm::dvec3(0, 0, 1));
    view.clipFromView = orthographic ? glm::orthoRH_NO(-2.0, 2.0, -2.0, 2.0, 0.0, 10.0)
                                     : glm::frustumRH_NO(-0.5, 0.5, -0.5, 0.5, 1.0, 10.0);
    c.grid = izb::makeLightGrid({view}, R, 10.0);
    c.light = orthographic ? izb::HomogeneousLight(glm::normalize(eye - target), 0.0) : izb::HomogeneousLight(eye, 1.0);
    const glm::dmat4 worldFromView = glm::inverse(view.viewFromWorld);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int k = 0; k < 20000; ++k) {
        double u = unit(rng) * R, v = unit(rng) * R;
        if (k % 5 == 0) u = std::round(u), v = k % 10 == 0 ? std::round(v) : v;
        const double depth = 3.0 + 4.0 * unit(rng);
        const double x = 2.0 * u / R - 1.0, y = 1.0 - 2.0 * v / R;
        const glm::dvec3 q = orthographic ? glm::dvec3(2.0 * x, 2.0 * y, -depth) : glm::dvec3(0.5 * x * depth, 0.5 * y * depth, -depth);
        c.receivers.push_back(glm::dvec3(worldFromView * glm::dvec4(q, 1.0)));
    }
    return c;
}

// Triangles of many sizes between the light and the receivers, some reaching behind the
// light's plane or beyond the view's sides.
void randomTriangle(std::mt19937& rng, glm::dvec3 (&t)[3]) {
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const double size = std::pow(10.0, 1.5 * unit(rng) - 0.5);
    const glm::dvec3 centre(1.5 * unit(rng), 2.5 + 3.0 * unit(rng), 1.5 * unit(rng));
    for (glm::dvec3& v : t) v = centre + size * glm::dvec3(unit(rng), unit(rng), unit(rng));
}

void checkCoverage(bool orthographic) {
    std::mt19937 rng(orthographic ? 11 : 12);
    const SmallCase c = smallCase(orthographic, rng);
    const int R = c.grid.resolution;
    REQUIRE(R <= izb::kTileSize);
    size_t shadowed = 0, missed = 0;
    for (int n = 0; n < 300; ++n) {
        glm::dvec3 triangle[3];
        randomTriangle(rng, triangle);
        const izb::LightPolygon polygon = izb::projectOccluder(c.grid, 0, triangle);
        const izb::TexelRange rows = izb::coveredRows(polygon, R);
        for (const glm::dvec3& o : c.receivers) {
            const glm::dvec3 towardsLight = glm::dvec3(c.light) - c.light.w * o;
            if (!izb::segmentBlocked(o, towardsLight, orthographic ? INFINITY : 1.0, triangle)) continue;
            ++shadowed;
            const uint32_t texel = izb::texelOf(c.grid, o);
            // The grid is one tile, so its texels are numbered row by row, kTileSize per row.
            const int j = int(texel / izb::kTileSize), i = int(texel % izb::kTileSize);
            const izb::TexelRange columns = izb::coveredColumns(polygon, j, j + 1, R);
            missed += !(j >= rows.begin && j < rows.end && i >= columns.begin && i < columns.end);
        }
    }
    MESSAGE(std::string(orthographic ? "orthographic" : "perspective") << ": " << shadowed << " shadowed (receiver, triangle) pairs");
    CHECK(shadowed > 100000);
    CHECK(missed == 0);
}

}  // namespace

TEST_CASE("izb coverage misses no texel of a receiver that a triangle shadows (perspective)") { checkCoverage(false); }
TEST_CASE("izb coverage misses no texel of a receiver that a triangle shadows (orthographic)") { checkCoverage(true); }

TEST_CASE("izb exact test: blocked strictly between the receiver and the light, shared edges never leak") {
    const glm::dvec3 light(0.0, 10.0, 0.0);
    // Two triangles of a unit square at y = 5 sharing the diagonal from (0,5,0) to (1,5,1).
    const glm::dvec3 a[3] = {{0, 5, 0}, {1, 5, 0}, {1, 5, 1}}, b[3] = {{0, 5, 0}, {1, 5, 1}, {0, 5, 1}};
    for (double s = 0.0; s <= 1.0; s += 1.0 / 64.0) {
        const glm::dvec3 o(s, 0.0, s);   // right under the shared diagonal
        CHECK((izb::segmentBlocked(o, light - o, 1.0, a) || izb::segmentBlocked(o, light - o, 1.0, b)));
    }
    const glm::dvec3 below(0.7, 0.0, 0.2), above(0.7, 6.0, 0.2);
    CHECK(izb::segmentBlocked(below, light - below, 1.0, a));
    CHECK_FALSE(izb::segmentBlocked(above, light - above, 1.0, a));          // the triangle is behind it
    CHECK_FALSE(izb::segmentBlocked(below, light - below, 0.4, a));          // the segment stops short
    const glm::dvec3 beside(3.0, 0.0, 0.2);
    CHECK_FALSE(izb::segmentBlocked(beside, light - beside, 1.0, a));
}

TEST_CASE("izb occluders projected once give projectOccluder's polygon, bit for bit, inside, across and outside the view") {
    for (bool orthographic : {false, true}) {
        std::mt19937 rng(orthographic ? 21 : 22);
        const SmallCase c = smallCase(orthographic, rng);
        WorldGeometry world;
        int wholeInside = 0, clipped = 0;
        for (uint32_t n = 0; n < 600; ++n) {
            glm::dvec3 t[3];
            randomTriangle(rng, t);
            for (const glm::dvec3& v : t) world.positions.push_back(glm::vec3(v));
            world.triangles.push_back({3 * n, 3 * n + 1, 3 * n + 2});
        }
        const izb::ProjectedOccluders occluders = izb::projectOccluders(c.grid, world);
        for (uint32_t n = 0; n < world.triangles.size(); ++n) {
            const glm::dvec3 t[3] = {glm::dvec3(world.positions[3 * n]), glm::dvec3(world.positions[3 * n + 1]),
                                     glm::dvec3(world.positions[3 * n + 2])};
            const izb::LightPolygon expected = izb::projectOccluder(c.grid, 0, t), got = occluders.polygon(c.grid, 0, n);
            REQUIRE(got.count == expected.count);
            CHECK(std::memcmp(got.vertex, expected.vertex, sizeof(glm::dvec2) * size_t(got.count)) == 0);
            const bool inside = occluders.inside[3 * n] && occluders.inside[3 * n + 1] && occluders.inside[3 * n + 2];
            wholeInside += inside, clipped += !inside;
        }
        CHECK(wholeInside > 50);   // both paths taken
        CHECK(clipped > 50);
    }
}
