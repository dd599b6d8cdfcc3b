// The float receiver pass of the shadow map (shadows/maps/lookup_kernel.h): the AVX2 and
// AVX-512 kernels against their scalar twin, bit for bit, over every filter, bias mode and
// selector; the reach stage against lightReaches() on receivers where a plain float test
// gets the sign wrong; and the float projection against the double one it replaced.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <utility>
#include <vector>

#include <tbb/parallel_for.h>

#include "raster/thread_count.h"
#include "shadows/maps/lookup_kernel.h"
#include "shadows/maps/min_max_hierarchy.h"
#include "shadows/maps/shadow_lookup.h"
#include "shadows/technique.h"
#include "shadow_map_test_util.h"
#include "tests/shadows/shadow_test_support.h"
#include "tests/same_bits.h"

using namespace shadowlab;
using test::sameBytes;

namespace {

// sphere-box at an odd width, so every row has a tail shorter than any vector.
struct LookupScene {
    Scene scene = loadScene("sphere-box");
    WorldGeometry world;
    GBuffer g;
    Light light;
    LookupScene() {
        scene.camera.width = 203, scene.camera.height = 131;
        world = flatten(scene);
        g = renderGBuffer(world, scene.camera, raster::SimdLevel::Scalar);
        light = pointLightFor(scene.lights[0]);
    }
    std::vector<DepthMap> maps(const BiasSettings& bias, int size) const { return maps(bias, size, light); }
    std::vector<DepthMap> maps(const BiasSettings& bias, int size, const Light& light) const {
        LightFitOptions fit;
        fit.resolution = size;
        DepthMapSettings settings;
        settings.size = size;
        settings.offset = polygonOffsetFor(bias);
        return {renderDepthMap(world, fitLightView(light, g, world, fit), settings, raster::SimdLevel::Scalar)};
    }
};

const LookupScene& lookupScene() {
    static const LookupScene s;
    return s;
}

std::vector<raster::SimdLevel> vectorLevels() {
    std::vector<raster::SimdLevel> levels;
    for (raster::SimdLevel l : {raster::SimdLevel::Avx2, raster::SimdLevel::Avx512}) {
        if (raster::simdLevelSupported(l)) levels.push_back(l);
    }
    return levels;
}

// Every row of the scene through `pass`, in parallel, each pixel served by the map where it
// is a hit.
void lookUpEveryRow(const LookupScene& s, const LookupPass& pass, const LookupPass::Outputs& out) {
    tbb::parallel_for(0, s.g.height, [&](int j) {
        LookupPass::Scratch scratch(s.g.width);
        for (int i = 0; i < s.g.width; ++i) scratch.served[size_t(i)] = s.g.hit[s.g.index(i, j)];
        pass.lookUpRow(s.g, j, scratch, out);
    });
}

}  // namespace

TEST_CASE("shadow lookup: every SIMD level and thread count gives the scalar twin's bytes, for every filter and bias") {
    const LookupScene& s = lookupScene();
    for (BiasMode mode : {BiasMode::Constant, BiasMode::SlopeScaled, BiasMode::NormalOffset, BiasMode::ReceiverPlane}) {
        BiasSettings bias;
        bias.mode = mode;
        const std::vector<DepthMap> maps = s.maps(bias, 256);
        for (FilterKind kind : {FilterKind::Nearest, FilterKind::Bilinear, FilterKind::Grid, FilterKind::Poisson}) {
            FilterSettings filter;
            filter.kind = kind;
            const PcfKernel kernel = makePcfKernel(filter);
            CAPTURE(int(mode));
            CAPTURE(int(kind));
            const ShadowLookup twin = withThreads(1, [&] {
                return lookUpShadows(s.g, s.scene.camera, s.light, maps, OneMap{}, bias, kernel, raster::SimdLevel::Scalar);
            });
            int lit = 0, partial = 0;
            for (float v : twin.visibility) lit += v == 1.0f, partial += v > 0.0f && v < 1.0f;
            CHECK(lit > 1000);   // a real image: most of the ground is lit
            if (kind != FilterKind::Nearest) CHECK(partial > 0);
            for (raster::SimdLevel level : vectorLevels()) {
                for (int threads : {1, 2}) {
                    const ShadowLookup v = withThreads(threads, [&] {
                        return lookUpShadows(s.g, s.scene.camera, s.light, maps, OneMap{}, bias, kernel, level);
                    });
                    CHECK(sameBytes(v.visibility, twin.visibility));
                }
            }
        }
    }
}

TEST_CASE("shadow lookup: a sun and a spot light give the scalar twin's bytes, and V = 0 outside the spot's cone") {
    const LookupScene& s = lookupScene();
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(4, 8, 3));
    Light spot = s.light;
    spot.type = LightType::Spot;
    spot.direction = glm::normalize(-spot.position);   // at the origin
    spot.coneAngleDeg = 20.0f;
    for (const Light& light : {sun, spot}) {
        for (BiasMode mode : {BiasMode::SlopeScaled, BiasMode::Constant}) {
            BiasSettings bias;
            bias.mode = mode;
            const std::vector<DepthMap> maps = s.maps(bias, 256, light);
            const PcfKernel kernel = makePcfKernel({FilterKind::Grid});
            const ShadowLookup twin = lookUpShadows(s.g, s.scene.camera, light, maps, OneMap{}, bias, kernel, raster::SimdLevel::Scalar);
            int lit = 0, outsideCone = 0, litOutsideCone = 0;
            for (size_t k = 0; k < twin.visibility.size(); ++k) {
                lit += twin.visibility[k] > 0.0f;
                if (light.type != LightType::Spot || !s.g.hit[k] || insideSpotCone(light, s.g.position[k])) continue;
                ++outsideCone, litOutsideCone += twin.visibility[k] != 0.0f;
            }
            CAPTURE(int(light.type));
            CHECK(lit > 1000);
            if (light.type == LightType::Spot) CHECK(outsideCone > 1000);
            CHECK(litOutsideCone == 0);
            for (raster::SimdLevel level : vectorLevels()) {
                const ShadowLookup v = lookUpShadows(s.g, s.scene.camera, light, maps, OneMap{}, bias, kernel, level);
                CHECK(sameBytes(v.visibility, twin.visibility));
            }
        }
    }
}

TEST_CASE("shadow lookup: PCSS gives the scalar twin's bytes at every SIMD level and thread count") {
    // The pcss filter on sphere-box's perspective map, a light 40 texels wide at 1 m: wide
    // penumbrae, so the blocker search, the width and the filter all matter.
    const LookupScene& s = lookupScene();
    BiasSettings plane;
    plane.mode = BiasMode::ReceiverPlane;
    const std::vector<DepthMap> maps = s.maps(plane, 512);
    const PcfKernel search = makePcfKernel({FilterKind::Poisson, 3, 16, 1.0});
    const PcfKernel filter = makePcfKernel({FilterKind::Poisson, 3, 32, 1.0});
    const auto run = [&](raster::SimdLevel level) {
        const LookupPass pass(maps[0], s.light, {search, 1.0, filter, glm::dvec2(40.0)}, level);
        const size_t n = s.g.pixelCount();
        std::vector<float> v(n), blocker(n), width(n);
        lookUpEveryRow(s, pass, {v.data(), blocker.data(), width.data()});
        v.insert(v.end(), blocker.begin(), blocker.end());
        v.insert(v.end(), width.begin(), width.end());
        return v;
    };
    const std::vector<float> twin = withThreads(1, [&] { return run(raster::SimdLevel::Scalar); });
    const size_t n = s.g.pixelCount();
    int penumbra = 0, blocked = 0;
    for (size_t k = 0; k < n; ++k) penumbra += twin[k] > 0.0f && twin[k] < 1.0f, blocked += twin[n + k] > 0.0f;
    CHECK(penumbra > 30);   // 65 of the 203 x 131 pixels
    CHECK(blocked > penumbra);
    test::checkSameBytesEverywhere(twin, run);
}

TEST_CASE("shadow lookup: contact hardening gives the scalar twin's bytes at every SIMD level and thread count") {
    // The chs filter on the same map as PCSS's case, reading the map's min/max hierarchy: a
    // light 40 texels wide at 1 m, whose cones span under 8 texels (the search reads texels),
    // and one 400 wide, whose cones the search reads on the hierarchy's levels; an even and
    // an odd filter grid.
    const LookupScene& s = lookupScene();
    BiasSettings plane;
    plane.mode = BiasMode::ReceiverPlane;
    const std::vector<DepthMap> maps = s.maps(plane, 512);
    const MinMaxHierarchy hierarchy(maps[0]);
    struct Case {
        double lightTexels;
        int searchNodes, filterNodes;
    };
    for (const Case& c : {Case{40.0, 8, 8}, Case{400.0, 8, 3}}) {
        CAPTURE(c.lightTexels);
        const auto run = [&](raster::SimdLevel level) {
            const LookupPass pass(maps[0], s.light,
                                  {c.searchNodes, c.filterNodes, glm::dvec2(c.lightTexels), hierarchy.forKernel()}, level);
            const size_t n = s.g.pixelCount();
            std::vector<float> v(n), blocker(n), width(n), searchLevel(n);
            lookUpEveryRow(s, pass, {v.data(), blocker.data(), width.data(), nullptr, searchLevel.data()});
            for (const std::vector<float>* image : {&blocker, &width, &searchLevel}) v.insert(v.end(), image->begin(), image->end());
            return v;
        };
        const std::vector<float> twin = withThreads(1, [&] { return run(raster::SimdLevel::Scalar); });
        const size_t n = s.g.pixelCount();
        int penumbra = 0, blocked = 0, onNodes = 0;
        for (size_t k = 0; k < n; ++k) {
            penumbra += twin[k] > 0.0f && twin[k] < 1.0f;
            blocked += twin[n + k] > 0.0f;
            onNodes += twin[3 * n + k] > 0.0f;
        }
        CAPTURE(penumbra);
        CAPTURE(onNodes);
        CHECK(penumbra > 30);
        CHECK(blocked > penumbra);
        if (c.lightTexels > 100.0) {
            CHECK(onNodes > blocked / 2);   // the wide cones' searches read the hierarchy's levels
        } else {
            CHECK(onNodes == 0);            // the narrow ones read texels
        }
        test::checkSameBytesEverywhere(twin, run);
    }
}

TEST_CASE("shadow lookup: the blocker search alone gives the scalar twin's bytes, and PCSS's blocker distances") {
    // The filtered maps' width=pcss search (kLookupBlockerSearch) is PCSS's steps 1 and 2:
    // the same d_o at every pixel as the pcss filter's, V = 1 where it found no blocker.
    const LookupScene& s = lookupScene();
    BiasSettings plane;
    plane.mode = BiasMode::ReceiverPlane;
    const std::vector<DepthMap> maps = s.maps(plane, 512);
    const PcfKernel search = makePcfKernel({FilterKind::Poisson, 3, 16, 1.0});
    const PcfKernel filter = makePcfKernel({FilterKind::Poisson, 3, 32, 1.0});
    const size_t n = s.g.pixelCount();
    const auto run = [&](const LookupPass& pass, bool pcss, int threads) {
        std::vector<float> v(n), blocker(n), width(n);
        withThreads(threads, [&] { lookUpEveryRow(s, pass, {v.data(), blocker.data(), pcss ? width.data() : nullptr}); });
        return std::pair(v, blocker);
    };
    const auto searchOnly = [&](raster::SimdLevel level, int threads) {
        return run(LookupPass(maps[0], s.light, LookupPass::BlockerSearch{search, 1.0, glm::dvec2(40.0)}, level), false,
                   threads);
    };
    const auto [twinV, twinBlocker] = searchOnly(raster::SimdLevel::Scalar, 1);
    const auto [pcssV, pcssBlocker] =
        run(LookupPass(maps[0], s.light, {search, 1.0, filter, glm::dvec2(40.0)}, raster::SimdLevel::Scalar), true, 1);
    CHECK(sameBytes(twinBlocker, pcssBlocker));
    int blocked = 0, wrong = 0;
    for (size_t k = 0; k < n; ++k) {
        blocked += twinBlocker[k] > 0.0f;
        const float expected = pcssV[k] == 0.0f && twinBlocker[k] == 0.0f ? 0.0f : twinBlocker[k] > 0.0f ? 0.0f : 1.0f;
        wrong += twinV[k] != expected;
    }
    CHECK(blocked > 30);
    CHECK(wrong == 0);
    for (raster::SimdLevel level : vectorLevels()) {
        for (int threads : {1, 2}) {
            const auto [v, blocker] = searchOnly(level, threads);
            CHECK(sameBytes(v, twinV));
            CHECK(sameBytes(blocker, twinBlocker));
        }
    }
}

TEST_CASE("shadow lookup: a vector across two maps takes each lane from its own map") {
    // Two different maps and a selector that alternates them in stripes 1.6 cm wide on the
    // ground, a few pixels each: many vectors hold lanes of both. Each lane must get what a
    // lookup with its own map alone gives.
    const LookupScene& s = lookupScene();
    std::vector<DepthMap> maps = s.maps({}, 256);
    maps.push_back(s.maps({}, 64)[0]);
    const PcfKernel kernel = makePcfKernel({});
    const auto alternate = [](const glm::dvec3& P) { return int(std::fabs(P.x) * 64.0) % 2; };
    std::vector<raster::SimdLevel> levels = vectorLevels();
    levels.push_back(raster::SimdLevel::Scalar);
    for (raster::SimdLevel level : levels) {
        const ShadowLookup both = lookUpShadows(s.g, s.scene.camera, s.light, maps, alternate, {}, kernel, level);
        const ShadowLookup first =
            lookUpShadows(s.g, s.scene.camera, s.light, std::span(&maps[0], 1), OneMap{}, {}, kernel, level);
        const ShadowLookup second =
            lookUpShadows(s.g, s.scene.camera, s.light, std::span(&maps[1], 1), OneMap{}, {}, kernel, level);
        int fromSecond = 0, mismatches = 0;
        for (size_t k = 0; k < both.visibility.size(); ++k) {
            if (both.mapIndex[k] < 0) continue;
            const float expected = both.mapIndex[k] == 0 ? first.visibility[k] : second.visibility[k];
            mismatches += both.visibility[k] != expected;
            fromSecond += both.mapIndex[k] == 1;
        }
        CHECK(fromSecond > 1000);
        CHECK(mismatches == 0);
        // The two maps disagree somewhere, so taking a lane from the wrong one would show.
        int disagree = 0;
        for (size_t k = 0; k < first.visibility.size(); ++k) disagree += first.visibility[k] != second.visibility[k];
        CHECK(disagree > 10);
    }
}

TEST_CASE("shadow lookup: the reach stage decides exactly as lightReaches, where float alone would not") {
    // Receivers whose plane passes within a hair of the light: dot(N, L - P) is a few float
    // roundings from zero, so a plain float dot gets its sign wrong on some of them.
    std::mt19937 random(7);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f), hair(-1e-6f, 1e-6f);
    Light light;
    light.type = LightType::Point;
    light.position = glm::vec3(4.1f, 8.3f, 3.7f);
    constexpr int kCount = 4096;   // a multiple of every width
    std::vector<glm::vec3> position(kCount), normal(kCount);
    int plainFloatWrong = 0;
    for (int k = 0; k < kCount; ++k) {
        const glm::vec3 P(10.0f * unit(random), 2.0f * unit(random), 10.0f * unit(random));
        const glm::vec3 L = light.position - P;
        // A unit normal nearly perpendicular to L.
        const glm::vec3 side = glm::normalize(glm::cross(L, glm::vec3(unit(random), unit(random), unit(random))));
        const glm::vec3 N = glm::normalize(side + hair(random) * glm::normalize(L));
        position[size_t(k)] = P, normal[size_t(k)] = N;
        const float plain = N.x * (light.position.x - P.x) + N.y * (light.position.y - P.y) + N.z * (light.position.z - P.z);
        plainFloatWrong += (plain > 0.0f) != lightReaches(light, P, N);
    }
    REQUIRE(plainFloatWrong > 0);   // the data provokes the failure the stage guards against
    for (raster::SimdLevel level : {raster::SimdLevel::Scalar, raster::SimdLevel::Avx2, raster::SimdLevel::Avx512}) {
        if (!raster::simdLevelSupported(level)) continue;
        const LookupKernels& kernels = lookupKernels(level);
        LookupConstants c{};
        c.reachAnchor[0] = light.position.x, c.reachAnchor[1] = light.position.y, c.reachAnchor[2] = light.position.z;
        std::vector<uint8_t> served(kCount, 1);
        LookupRow row{};
        row.position = &position[0].x, row.normal = &normal[0].x, row.served = served.data(), row.count = kCount;
        kernels.reach(c, row);
        int undecided = 0, wrong = 0;
        for (int k = 0; k < kCount; ++k) {
            const uint8_t s = served[size_t(k)];
            undecided += (s & kReachUndecided) != 0;
            if (!(s & kReachUndecided)) wrong += (s == 1) != lightReaches(light, position[size_t(k)], normal[size_t(k)]);
        }
        CAPTURE(raster::simdLevelName(level));
        CHECK(wrong == 0);
        CHECK(undecided >= plainFloatWrong);   // at least the lanes plain float gets wrong are left to double
        CHECK(undecided < kCount / 2);         // and the certificate still decides most of these hard ones
    }
}

TEST_CASE("shadow lookup: the float projection stays within 1e-3 texel and 6 float steps of depth of the double one") {
    // The projection stage's receivers against mapReceiver() in double, for every pixel
    // of sphere-box, under every bias mode; for receiver planes also the plane's depth
    // slope (relative) and the tolerance it gives.
    const LookupScene& s = lookupScene();
    for (BiasMode mode : {BiasMode::Constant, BiasMode::SlopeScaled, BiasMode::NormalOffset, BiasMode::ReceiverPlane}) {
        BiasSettings bias;
        bias.mode = mode;
        const std::vector<DepthMap> maps = s.maps(bias, 2048);
        const LookupPass pass(maps, s.light, bias, makePcfKernel({}), raster::SimdLevel::Scalar);
        double worstTexel = 0.0, worstDepth = 0.0, worstSlope = 0.0, worstTolerance = 0.0;
        for (int j = 0; j < s.g.height; ++j) {
            LookupPass::Scratch scratch(s.g.width);
            for (int i = 0; i < s.g.width; ++i) scratch.served[size_t(i)] = s.g.hit[s.g.index(i, j)];
            std::vector<float> visibility(s.g.pixelCount());
            pass.lookUpRow(s.g, j, scratch, {visibility.data()});
            const size_t n = size_t(s.g.width);
            const float* texelX = scratch.receivers.data();
            const float *texelY = texelX + n, *depth = texelX + 2 * n, *slopeX = texelX + 3 * n, *slopeY = texelX + 4 * n,
                        *tolerance = texelX + 5 * n;
            for (size_t i = 0; i < n; ++i) {
                if (!scratch.served[i]) continue;
                const size_t k = s.g.index(int(i), j);
                const MapReceiver r = mapReceiverFromPoint(maps[0], glm::dvec3(s.g.position[k]), glm::dvec3(s.g.normal[k]),
                                                           glm::dvec3(s.light.position), bias);
                worstTexel = std::max({worstTexel, std::abs(texelX[i] - r.texel.x), std::abs(texelY[i] - r.texel.y)});
                worstDepth = std::max(worstDepth, std::abs(depth[i] - r.depth));
                if (mode != BiasMode::ReceiverPlane) continue;
                const double slopeSize = std::abs(r.depthSlope.x) + std::abs(r.depthSlope.y);
                worstSlope = std::max(worstSlope, (std::abs(slopeX[i] - r.depthSlope.x) + std::abs(slopeY[i] - r.depthSlope.y)) / slopeSize);
                worstTolerance = std::max(worstTolerance, std::abs(tolerance[i] - r.tolerance) / r.tolerance);
            }
        }
        CAPTURE(int(mode));
        CHECK(worstTexel > 0.0);   // float really differs: the comparison is not vacuous
        CHECK(worstTexel < 1e-3);
        CHECK(worstDepth < 6.0 / 16777216.0);   // 3.6 steps measured
        CHECK(worstSlope < 1e-4);       // 3.5e-6 measured
        CHECK(worstTolerance < 1e-4);
    }
}
