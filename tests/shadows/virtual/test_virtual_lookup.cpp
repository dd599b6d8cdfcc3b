// The virtual shadow map's filtered and soft lookups (shadows/virtual/page_lookup.h, smrt.h):
// PCF through the page table gives the shadow maps' PCF on the same texels, the technique's
// PCF is the same bytes everywhere and scores against the reference as shadow-map's does;
// shadow-map ray tracing reads only marked pages, gives the hard shadow for a point-like sun,
// the same bytes on any thread count, and beats the hard shadow against a sized sun's.
#include <doctest/doctest.h>

#include <algorithm>
#include <map>

#include <glm/gtc/matrix_transform.hpp>

#include "raster/thread_count.h"
#include "scenes/bounds.h"
#include "shadows/maps/shadow_lookup.h"
#include "shadows/virtual/page_lookup.h"
#include "shadows/virtual/smrt.h"
#include "tests/frame/technique_scenes.h"
#include "tests/shadows/shadow_test_support.h"
#include "tests/shadows/soft_test_support.h"

using namespace shadowlab;
using namespace shadowlab::vsm;

// Named, so that a unity build of the tests meets no other file's helpers.
namespace virtual_lookup_test {

Scene pagedSunScene() { return test::smallScene(test::sunScene(), 320, 200); }

// The stages of the technique up to its lookup (virtual_shadow_map.cpp), on a small map:
// levels marked with the filter's reach, every marked page drawn.
struct PagedSun {
    const test::HardScene& s;
    ClipmapSettings clipmap{.resolution = 4096, .pageTexels = 64, .firstLevel = -2, .lastLevel = 10};
    LightFrame frame;
    vsm::DepthRange range;   // vsm::, for a unity build where shadowlab has one too
    PageTable table{clipmap, 4096};
    PagePool pool{clipmap.pageTexels, {}};
    std::vector<PixelLevel> levels;

    // rays: the reach of shadow-map ray tracing's rays in a cone of this half-angle, if any.
    PagedSun(const test::HardScene& scene, const BiasSettings& bias, const FilterSettings& filter,
             const SmrtSettings& rays = {}, double halfAngle = 0.0)
        : s(scene), frame(LightFrame::towards(glm::normalize(glm::dvec3(s.scene.lights[0].direction)))) {
        const std::vector<Aabb> boxes = instanceBounds(s.prepared.scene(), s.prepared.world());
        range = depthRangeOf(boxes, frame);
        std::vector<LevelWindow> windows;
        for (int l = clipmap.firstLevel; l <= clipmap.lastLevel; ++l)
            windows.push_back(placeLevel(clipmap, l, frame.local(glm::dvec3(s.scene.camera.eye))));
        table.beginFrame(windows);
        markPages(s.gbuffer, s.scene.camera, s.scene.lights[0], frame, clipmap,
                  {0, lookupReachTexels(bias, filter), smrtReach(rays, halfAngle, range)}, table, levels);
        const std::vector<PageKey> keys = table.allocate();
        std::vector<int32_t> physical;
        for (const PageKey& k : keys) physical.push_back(table.physical(k));
        PageDrawing drawing;
        renderPages(s.prepared, boxes, frame, clipmap, range, keys, physical, polygonOffsetFor(bias),
                    raster::SimdLevel::Scalar, drawing, pool);
        for (const PageKey& k : keys) table.markRendered(k);
    }

    // The level most pixels read (index from the first).
    int commonLevel() const {
        std::map<int, size_t> count;
        for (const PixelLevel& p : levels)
            if (p.level != kNoLevel) ++count[p.level];
        return std::max_element(count.begin(), count.end(), [](auto& a, auto& b) { return a.second < b.second; })->first;
    }

    // An ordinary depth map of that level's texels: the square of pages from the level's
    // first marked page, each texel copied from its page (1, empty, where none is valid).
    DepthMap levelAsMap(int levelIndex) const {
        const int level = clipmap.firstLevel + levelIndex, n = clipmap.pagesPerSide(), t = clipmap.pageTexels;
        const LevelWindow& w = table.windows()[size_t(levelIndex)];
        int32_t x0 = w.firstX + n, y0 = w.firstY + n, x1 = w.firstX - 1, y1 = w.firstY - 1;
        for (int32_t y = w.firstY; y < w.firstY + n; ++y)
            for (int32_t x = w.firstX; x < w.firstX + n; ++x)
                if (table.requested({level, x, y})) x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
        DepthMap map;
        map.size = int(std::max(x1 - x0 + 1, y1 - y0 + 1)) * t;
        map.tilesX = (map.size + raster::kTileSize - 1) / raster::kTileSize;
        map.depth.assign(size_t(map.tilesX) * size_t(map.tilesX) * raster::kPixelsPerTile, 1.0f);
        const PageTexels texels(clipmap.pageTexels, table, pool);
        for (int y = 0; y < map.size; ++y) {
            for (int x = 0; x < map.size; ++x) {
                const float d = texels.at(level, int(x0) * t + x, int(y0) * t + y);
                if (d != PageTexels::kMissingTexel) map.depth[raster::blockLinearIndex(x, y, map.tilesX)] = d;
            }
        }
        map.texelFromWorld = glm::translate(glm::dmat4(1.0), glm::dvec3(-double(x0) * t, -double(y0) * t, 0.0)) *
                             levelTexelFromWorld(frame, clipmap, range, level);
        map.worldFromTexel = glm::inverse(map.texelFromWorld);
        return map;
    }
};

struct Agreement {
    size_t compared = 0, fractional = 0, differing = 0;
};

// Over the pixels of one level: how many the two lookups answer differently (by more than
// float's rounding of a bilinear weight), and how many have a fractional V.
Agreement agreement(const PagedSun& p, int levelIndex, const std::vector<float>& a, const std::vector<float>& b) {
    Agreement out;
    for (size_t k = 0; k < a.size(); ++k) {
        if (p.levels[k].level != levelIndex) continue;
        ++out.compared;
        out.fractional += (a[k] > 0.0f && a[k] < 1.0f) || (b[k] > 0.0f && b[k] < 1.0f);
        out.differing += std::abs(a[k] - b[k]) > 2e-3f;
    }
    return out;
}

}  // namespace virtual_lookup_test

using namespace virtual_lookup_test;

TEST_CASE("virtual-shadow-map: PCF through the pages equals shadow-map's PCF on the same texels") {
    const test::HardScene s(pagedSunScene());
    FilterSettings grid{FilterKind::Grid}, poisson{FilterKind::Poisson};
    poisson.poissonRadiusTexels = 2.5;
    for (const FilterSettings& filter : {FilterSettings{}, FilterSettings{FilterKind::Bilinear}, grid, poisson}) {
        INFO("filter " << int(filter.kind));
        const BiasSettings bias{};
        const PagedSun p(s, bias, filter);
        const PcfKernel kernel = makePcfKernel(filter);
        const LookupResult virtualMap = lookUpPages(s.gbuffer, s.scene.lights[0], p.frame, p.clipmap, p.range, bias,
                                                    kernel, p.levels, p.table, p.pool);
        CHECK(virtualMap.missingPixels == 0);
        // shadow-map's float lookup (its filter kernels) on one level copied into a map.
        const int level = p.commonLevel();
        const DepthMap map = p.levelAsMap(level);
        const std::vector<float> shadowMap =
            lookUpShadows(s.gbuffer, s.scene.camera, s.scene.lights[0], {&map, 1}, OneMap{}, bias, kernel,
                          raster::SimdLevel::Scalar)
                .visibility;
        const Agreement a = agreement(p, level, virtualMap.visibility, shadowMap);
        INFO(a.compared << " pixels compared, " << a.fractional << " fractional, " << a.differing << " differing");
        CHECK(a.compared > 10000);
        // Float and double place a receiver up to 5e-4 texel apart (shadow_lookup.h), which
        // moves a tap across a texel border at a handful of pixels.
        CHECK(a.differing <= a.compared / 2000 + 2);
        if (filter.kind != FilterKind::Nearest) CHECK(a.fractional > 200);
        // The bound can fail: another filter on the same texels misses it by far.
        if (filter.kind == FilterKind::Grid) {
            const std::vector<float> bilinear =
                lookUpShadows(s.gbuffer, s.scene.camera, s.scene.lights[0], {&map, 1}, OneMap{}, bias,
                              makePcfKernel({FilterKind::Bilinear}), raster::SimdLevel::Scalar)
                    .visibility;
            CHECK(agreement(p, level, virtualMap.visibility, bilinear).differing > a.compared / 200);
        }
    }
}

TEST_CASE("virtual-shadow-map: PCF is the same bytes on every thread count and SIMD level") {
    const test::HardScene s(pagedSunScene());
    const std::map<std::string, std::string> params{
        {"virtual-resolution", "4096"}, {"page-texels", "64"}, {"filter", "poisson"}, {"poisson-radius", "2"}};
    const std::vector<float> twin = s.run("virtual-shadow-map", params, raster::SimdLevel::Scalar).visibility;
    test::checkSameBytesEverywhere(twin, [&](raster::SimdLevel level) {
        return s.run("virtual-shadow-map", params, level).visibility;
    });
}

TEST_CASE("virtual-shadow-map: PCF against the reference within shadow-map's PCF") {
    const test::HardScene s(pagedSunScene());
    for (const std::string filter : {"bilinear", "grid", "poisson"}) {
        INFO("filter " << filter);
        const ShadowOutputs out = s.run("virtual-shadow-map", {{"filter", filter}});
        const ShadowOutputs map = s.run("shadow-map", {{"filter", filter}});
        double sum = 0.0, mapSum = 0.0;
        size_t n = 0;
        for (size_t k = 0; k < s.reference.size(); ++k) {
            if (!s.gbuffer.hit[k]) continue;
            sum += std::abs(double(out.visibility[k]) - s.reference[k]);
            mapSum += std::abs(double(map.visibility[k]) - s.reference[k]);
            ++n;
        }
        const double mean = sum / double(n), mapMean = mapSum / double(n);
        INFO("mean |V - reference|: virtual map " << mean << ", shadow-map " << mapMean);
        CHECK(test::stat(out, "cache_missing_pixels") == 0);
        // A filter blurs the hard edge over its taps' texels: the virtual map's match the
        // pixel's footprint, coarser here than shadow-map's 2048 texels over the sun case
        // (a mean of 0.0006 / 0.0059 / 0.048 for bilinear / 3 x 3 grid / poisson, against
        // 0.0002 / 0.0043 / 0.047). Within half as much again; a misplaced tap or a wrong
        // weight costs far more.
        CHECK(mean <= 1.5 * mapMean + 5e-4);
    }
}

namespace virtual_lookup_test {

// reference-soft's V for the sun of the scene given this half-angle (256 directions of its
// cap per pixel).
std::vector<float> sizedSunReference(const test::HardScene& s, double halfAngle) {
    Light sun = s.scene.lights[0];
    sun.angularDiameterDeg = float(glm::degrees(2.0 * halfAngle));
    return ReferenceVisibility(s.world, &s.transmission).visibility(s.gbuffer, sun, {.areaSamplesPerAxis = 16});
}

SmrtResult traceRays(const PagedSun& p, const SmrtSettings& rays, double halfAngle) {
    const MarkingSettings marking{0, lookupReachTexels({}, {}), smrtReach(rays, halfAngle, p.range)};
    return traceShadowMapRays(p.s.gbuffer, p.s.scene.lights[0], p.frame, p.clipmap, p.range, BiasSettings{}, rays,
                              marking, p.levels, p.table, p.pool);
}

double rmsAgainst(const test::HardScene& s, const std::vector<float>& v, const std::vector<float>& reference) {
    double sum = 0.0;
    size_t n = 0;
    for (size_t k = 0; k < v.size(); ++k) {
        if (!s.gbuffer.hit[k]) continue;
        sum += (double(v[k]) - reference[k]) * (double(v[k]) - reference[k]), ++n;
    }
    return std::sqrt(sum / double(n));
}

constexpr double kHalfAngle = 0.05;   // about 2.9 degrees: a penumbra of 5 cm per m of height

}  // namespace virtual_lookup_test

TEST_CASE("virtual-shadow-map: no ray reads a page marking did not mark, and without the rays' reach some would") {
    const test::HardScene s(pagedSunScene());
    const SmrtSettings rays{.rays = 8, .steps = 8};
    const PagedSun marked(s, {}, {}, rays, kHalfAngle);
    const SmrtResult traced = traceRays(marked, rays, kHalfAngle);
    CHECK(traced.missingReads == 0);
    CHECK(traced.lookup.missingPixels == 0);
    const PagedSun hardOnly(s, {}, {});
    CHECK(traceRays(hardOnly, rays, kHalfAngle).missingReads > 0);
}

TEST_CASE("virtual-shadow-map: a point-like sun's rays give the hard lookup's shadow") {
    const test::HardScene s(pagedSunScene());
    const SmrtSettings rays{.rays = 4, .steps = 8};
    const PagedSun p(s, {}, {}, rays, 0.0);
    const std::vector<float> hard =
        lookUpPages(s.gbuffer, s.scene.lights[0], p.frame, p.clipmap, p.range, {}, makePcfKernel({}), p.levels,
                    p.table, p.pool)
            .visibility;
    const std::vector<float> traced = traceRays(p, rays, 0.0).lookup.visibility;
    size_t differing = 0, shadowed = 0;
    for (size_t k = 0; k < hard.size(); ++k) differing += hard[k] != traced[k], shadowed += hard[k] == 0.0f && s.gbuffer.hit[k];
    // Every ray runs along the beam over the receiver's own texel: in front all the way
    // where the hard lookup is lit, behind until it crosses the occluder where it is not.
    CHECK(shadowed > 1000);
    CHECK(differing <= hard.size() / 2000);
}

TEST_CASE("virtual-shadow-map: shadow-map ray tracing is the same bytes on 1 and 2 threads") {
    const test::HardScene s(pagedSunScene());
    const SmrtSettings rays{.rays = 8, .steps = 8};
    const PagedSun p(s, {}, {}, rays, kHalfAngle);
    const std::vector<float> one = withThreads(1, [&] { return traceRays(p, rays, kHalfAngle).lookup.visibility; });
    const std::vector<float> two = withThreads(2, [&] { return traceRays(p, rays, kHalfAngle).lookup.visibility; });
    CHECK(test::sameBytes(one, two));
}

TEST_CASE("virtual-shadow-map: shadow-map ray tracing against a sized sun's exact soft shadow") {
    const test::HardScene s(pagedSunScene());
    const std::vector<float> reference = sizedSunReference(s, kHalfAngle);
    const PagedSun hardOnly(s, {}, {});
    const double hard = rmsAgainst(s, lookUpPages(s.gbuffer, s.scene.lights[0], hardOnly.frame, hardOnly.clipmap,
                                           hardOnly.range, {}, makePcfKernel({}), hardOnly.levels, hardOnly.table,
                                           hardOnly.pool)
                                   .visibility,
                            reference);
    for (int rayCount : {4, 16}) {
        const SmrtSettings rays{.rays = rayCount, .steps = 8};
        const PagedSun p(s, {}, {}, rays, kHalfAngle);
        const SmrtResult traced = traceRays(p, rays, kHalfAngle);
        const double soft = rmsAgainst(s, traced.lookup.visibility, reference);
        double escaped = 0.0;
        for (float e : traced.escapedRays) escaped += e;
        INFO(rayCount << " rays: RMS " << soft << " against the hard lookup's " << hard << ", " << escaped
                      << " rays escaped");
        // 16 rays: about 0.016 against 0.023 (7 December 2026); 4 rays are noisier.
        CHECK(soft < (rayCount == 4 ? 0.95 : 0.75) * hard);
        CHECK(escaped > 10.0);   // the depth history made an inner penumbra (22 to 24 here)
    }
}

TEST_CASE("virtual-shadow-map: smrt-rays on a point-like sun keeps the hard shadow, and 0 rays is the default's bytes") {
    const test::HardScene s(pagedSunScene());
    const ShadowOutputs hard = s.run("virtual-shadow-map");
    CHECK(test::sameBytes(s.run("virtual-shadow-map", {{"smrt-rays", "0"}}).visibility, hard.visibility));
    // hard/sun's sun is point-like: every ray runs along the beam.
    const ShadowOutputs rays = s.run("virtual-shadow-map", {{"smrt-rays", "4"}});
    CHECK(test::misclassified(s.gbuffer, s.reference, s.light(), rays.visibility).percent() <= 0.05);
    CHECK(test::stat(rays, "smrt_missing_read_count") == 0);
    CHECK(test::stat(rays, "cache_missing_pixels") == 0);
}

TEST_CASE("virtual-shadow-map: shadow-map ray tracing on the sized sun of soft/sun-disk against reference-soft") {
    // A 2.5-degree sun over a 5 m post, a canopy and a ball (docs/hard-cases.md), at 320 x 200.
    const test::SoftScene s(test::smallScene(test::softCase("sun-disk"), 320, 200), 16);
    const ShadowOutputs hard = s.run("virtual-shadow-map");
    const ShadowOutputs rays = s.run("virtual-shadow-map", {{"smrt-rays", "16"}});
    INFO("RMS: hard " << s.rms(hard.visibility) << ", 16 rays " << s.rms(rays.visibility));
    CHECK(test::stat(rays, "smrt_missing_read_count") == 0);
    // 640 x 400: 0.044 hard, 0.018 with 16 rays (docs/virtual-shadow-maps.md).
    CHECK(s.rms(rays.visibility) < 0.6 * s.rms(hard.visibility));
}

TEST_CASE("virtual-shadow-map: a sun's rays read only marked pages where their boxes leave a level's window") {
    // Levels of 256 texels are two pages of 128 a side: many pixels' rays' boxes leave a
    // level's window, and their samples must read the coarser level marking marked instead
    // (heldRayLevel; before it, 477 reads of 16000 pixels' rays found no page here).
    const test::SoftScene s(test::smallScene(test::softCase("sun-disk"), 160, 100), 8);
    const std::map<std::string, std::string> coarse{{"virtual-resolution", "256"}};
    auto withRays = coarse;
    withRays.emplace("smrt-rays", "16");
    const ShadowOutputs rays = s.run("virtual-shadow-map", withRays);
    CHECK(test::stat(rays, "smrt_missing_read_count") == 0);
    CHECK(test::stat(rays, "cache_missing_pixels") == 0);
    // And they still trace the penumbra there (rays cut short would not): 0.032 against
    // the hard lookup's 0.053 (7 December 2026).
    const double hard = s.rms(s.run("virtual-shadow-map", coarse).visibility), soft = s.rms(rays.visibility);
    INFO("RMS at 256 texels a level: hard " << hard << ", 16 rays " << soft);
    CHECK(soft < 0.75 * hard);
}

TEST_CASE("virtual-shadow-map: a sun's receiver biased above the depth range sends no rays, and reads no missing page") {
    const test::SoftScene s(test::smallScene(test::softCase("sun-disk"), 160, 100), 8);
    const std::map<std::string, std::string> lifted{{"bias", "constant"}, {"constant-bias", "100"}};
    auto withRays = lifted;
    withRays.emplace("smrt-rays", "4");
    const ShadowOutputs rays = s.run("virtual-shadow-map", withRays);
    CHECK(test::stat(rays, "smrt_missing_read_count") == 0);
    CHECK(test::stat(rays, "cache_missing_pixels") == 0);
    // Every receiver lies above the range's top: the hard lookup's answer, lit everywhere.
    CHECK(test::sameBytes(rays.visibility, s.run("virtual-shadow-map", lifted).visibility));
}
