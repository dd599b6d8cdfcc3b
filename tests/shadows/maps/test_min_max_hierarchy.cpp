// The min/max depth hierarchy (shadows/maps/min_max_hierarchy.h; RTR 7.6) and the PCSS taps
// it lets the lookup skip: its nodes bound their texels, and PCSS gives the same bits with
// it as without, at every SIMD level and thread count.
#include <doctest/doctest.h>

#include <algorithm>
#include <map>
#include <string>

#include <tbb/global_control.h>

#include "frame/registry.h"
#include "frame/render.h"
#include "raster/tile_kernels.h"
#include "scenes/hash_random.h"
#include "scenes/scene_file.h"
#include "shadows/maps/min_max_hierarchy.h"
#include "shadows/technique.h"
#include "tests/shadows/soft_test_support.h"

using namespace shadowlab;

namespace {

// A size x size map of random depths, a quarter of them empty (1), in blocks of 3 x 3 so
// that nodes see both runs and edges.
DepthMap randomMap(int size, uint64_t seed) {
    DepthMap map;
    map.size = size;
    map.tilesX = (size + raster::kTileSize - 1) / raster::kTileSize;
    map.depth.resize(size_t(map.tilesX) * size_t(map.tilesX) * raster::kPixelsPerTile);
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const uint64_t h = mix64(seed * 7919u + uint64_t(x / 3) * 104729u + uint64_t(y / 3)) ^ uint64_t(x * 31 + y);
            const float depth = (h % 4 == 0) ? 1.0f : float(h % 1000) / 1000.0f;
            map.depth[raster::blockLinearIndex(x, y, map.tilesX)] = depth;
        }
    }
    return map;
}

DepthMap floorMap(int size) {
    DepthMap map = randomMap(size, 3);
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const float z = (x * 37 + y * 11) % 97 == 0 ? 1.0f : 0.5f + 0.001f * float(x) + 0.0003f * float(y);
            map.depth[raster::blockLinearIndex(x, y, map.tilesX)] = z;
        }
    }
    return map;
}

DepthRange bruteRange(const DepthMap& map, int x0, int y0, int x1, int y1) {
    DepthRange r;
    for (int y = std::max(y0, 0); y <= std::min(y1, map.size - 1); ++y) {
        for (int x = std::max(x0, 0); x <= std::min(x1, map.size - 1); ++x) {
            r.least = std::min(r.least, map.at(x, y)), r.greatest = std::max(r.greatest, map.at(x, y));
        }
    }
    return r;
}

}  // namespace

TEST_CASE("each node of a min-max hierarchy holds exactly the range of its texels and bounds them by its plane") {
    for (int size : {2, 3, 5, 64, 100, 129}) {
        CAPTURE(size);
        // Random blocks, and a sloped floor with holes, whose planes the nodes fit closely.
        const DepthMap map = size % 2 ? randomMap(size, uint64_t(size)) : floorMap(size);
        const MinMaxHierarchy h(map);
        CHECK(h.sizeOf(h.levels()) == 1);
        for (int level = MinMaxHierarchy::kFirstLevel; level <= h.levels(); ++level) {
            CAPTURE(level);
            REQUIRE(h.sizeOf(level) == (size + (1 << level) - 1) >> level);
            for (int y = 0; y < h.sizeOf(level); ++y) {
                for (int x = 0; x < h.sizeOf(level); ++x) {
                    const int w = 1 << level;
                    const DepthRange want = bruteRange(map, x * w, y * w, x * w + w - 1, y * w + w - 1);
                    REQUIRE(h.node(level, x, y).least == want.least);
                    REQUIRE(h.node(level, x, y).greatest == want.greatest);
                    // Every solid texel within the node's plane plus its residuals.
                    const NodePlane p = h.plane(level, x, y);
                    for (int ty = y * w; ty < std::min(y * w + w, size); ++ty) {
                        for (int tx = x * w; tx < std::min(x * w + w, size); ++tx) {
                            const double z = map.at(tx, ty);
                            const double fit = double(p.depth) + double(p.slopeX) * (tx + 0.5 - (x + 0.5) * w) +
                                               double(p.slopeY) * (ty + 0.5 - (y + 0.5) * w);
                            if (z < 1.0) REQUIRE(z - fit >= double(p.residualLow));
                            REQUIRE(z - fit <= double(p.residualHigh));
                        }
                    }
                }
            }
        }
    }
}

TEST_CASE("a min-max hierarchy query bounds every texel of the rectangle and meets at most four nodes") {
    const DepthMap map = randomMap(100, 7);
    const MinMaxHierarchy h(map);
    for (uint64_t k = 0; k < 2000; ++k) {
        const int x0 = int(mix64(11 + 16 * k) % 120) - 10, y0 = int(mix64(12 + 16 * k) % 120) - 10;
        const int x1 = x0 + int(mix64(13 + 16 * k) % 40), y1 = y0 + int(mix64(14 + 16 * k) % 40);
        const DepthRange want = bruteRange(map, x0, y0, x1, y1), got = h.over(x0, y0, x1, y1);
        INFO(x0 << " " << y0 << " " << x1 << " " << y1);
        REQUIRE(got.least <= want.least);
        REQUIRE(got.greatest >= want.greatest);
        const int level = hierarchyLevelFor(std::min(x1, 99) - std::max(x0, 0), h.levels());
        REQUIRE(((std::min(x1, 99) >> level) - (std::max(x0, 0) >> level)) <= 1);
    }
    CHECK(hierarchyLevelFor(0, 7) == 2);
    CHECK(hierarchyLevelFor(3, 7) == 2);
    CHECK(hierarchyLevelFor(4, 7) == 3);
    CHECK(hierarchyLevelFor(1000, 7) == 7);
}

TEST_CASE("a min-max hierarchy proves a region lit only where every texel is lit, for random receiver planes") {
    // A sloped floor with holes and random blocks above it; receivers on random planes near
    // the floor's, some exactly on it. Every proof is checked against litBy at every texel.
    for (int size : {64, 100}) {
        DepthMap map = floorMap(size);
        for (int k = 0; k < 12; ++k) {   // blocks of occluders a little above the floor
            const int bx = int(mix64(100 + uint64_t(k)) % uint64_t(size));
            const int by = int(mix64(200 + uint64_t(k)) % uint64_t(size));
            for (int y = by; y < std::min(by + 3, size); ++y) {
                for (int x = bx; x < std::min(bx + 3, size); ++x) {
                    map.depth[raster::blockLinearIndex(x, y, map.tilesX)] -= 0.002f;
                }
            }
        }
        const MinMaxHierarchy h(map);
        int proved = 0;
        for (uint64_t k = 0; k < 3000; ++k) {
            MapReceiver r;
            r.texel = {double(mix64(300 + k) % 6400) / 100.0, double(mix64(400 + k) % 6400) / 100.0};
            // On the floor, nearer the light than it (lit), or deeper (shadowed by the floor).
            const double lift = double(k % 3) * 0.5 * (double(mix64(500 + k) % 1000) - 1000.0) * 2e-6 * (k % 3 == 2 ? -1 : 1);
            r.depthSlope = k % 2 ? glm::dvec2(0.001, 0.0003) : glm::dvec2(0.001 + 1e-5 * double(k % 7), 0.0003);
            r.depth = 0.5 + 0.001 * (r.texel.x - 0.5) + 0.0003 * (r.texel.y - 0.5) + lift;
            r.tolerance = 4e-6;
            const int x0 = int(r.texel.x) - int(k % 9), y0 = int(r.texel.y) - int(k % 5);
            const int x1 = int(r.texel.x) + int(k % 11), y1 = int(r.texel.y) + int(k % 13);
            if (!h.provedLit(r, x0, y0, x1, y1)) continue;
            ++proved;
            for (int y = y0; y <= y1; ++y) {
                for (int x = x0; x <= x1; ++x) REQUIRE(r.litBy(map, x, y));
            }
        }
        CAPTURE(size);
        CAPTURE(proved);
        CHECK(proved > 100);   // on the floor itself the planes prove a good share (217, 833)
    }
}

TEST_CASE("pcss gives the same bits with and without the min-max hierarchy, at every SIMD level and thread count") {
    for (const std::string& name :
         {std::string("sphere-box"), test::softCase("two-boxes"), test::softCase("large-light")}) {
        CAPTURE(name);
        Scene scene = loadScene(name);
        scene.camera.width = 200, scene.camera.height = 125;
        const PreparedScene prepared(std::move(scene));
        const GBuffer g = renderGBuffer(prepared.world(), prepared.scene().camera, raster::SimdLevel::Scalar);
        const Technique& pcss = findTechnique("pcss");
        const auto run = [&](const std::string& hierarchy, raster::SimdLevel simd) {
            const TechniqueParams params(pcss.name, pcss.params, {{"min-max-hierarchy", hierarchy}});
            return pcss.run({.prepared = prepared,
                             .gbuffer = g,
                             .light = prepared.scene().lights[0],
                             .simd = simd,
                             .params = params});
        };
        const ShadowOutputs plain = run("off", raster::SimdLevel::Scalar);
        for (int threads : {1, 2}) {
            const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(threads));
            for (raster::SimdLevel level :
                 {raster::SimdLevel::Scalar, raster::SimdLevel::Avx2, raster::SimdLevel::Avx512}) {
                if (!raster::simdLevelSupported(level)) continue;
                CAPTURE(raster::simdLevelName(level));
                CAPTURE(threads);
                const ShadowOutputs proved = run("on", level);
                REQUIRE(proved.visibility == plain.visibility);
                const auto known = std::find_if(proved.stats.begin(), proved.stats.end(), [](const TechniqueStat& s) {
                    return s.name == "hierarchy_known_taps_percent";
                });
                REQUIRE(known != proved.stats.end());
                CHECK(known->value > 1.0);
            }
        }
    }
}
