// The virtual shadow map's page bookkeeping (shadows/virtual/: clipmap, page_table,
// page_marking, page_invalidation) on the sun case: marking is conservative, a still frame
// after a first one needs no page, a sub-page camera move keeps every page it still needs,
// eviction never takes a page requested this frame, a moved box invalidates exactly the
// pages a brute-force overlap test finds, and marking is the same on any thread count.
#include <doctest/doctest.h>

#include <set>
#include <tuple>
#include <vector>

#include "raster/thread_count.h"
#include "scenes/scene_file.h"
#include "shadows/camera_pass.h"
#include "shadows/virtual/page_invalidation.h"
#include "shadows/virtual/page_lookup.h"
#include "shadows/virtual/page_marking.h"

using namespace shadowlab;
using namespace shadowlab::vsm;

namespace {

using KeySet = std::set<std::tuple<int, int32_t, int32_t>>;

struct SunView {
    Scene scene;
    GBuffer gbuffer;
    LightFrame frame;

    explicit SunView(const glm::vec3& eyeShift = glm::vec3(0.0f)) {
        scene = loadScene(std::string(SHADOWLAB_SOURCE_DIR) + "/assets/scenes/hard/sun.json");
        scene.camera.width = 160;
        scene.camera.height = 100;
        scene.camera.eye += eyeShift;
        scene.camera.target += eyeShift;
        const WorldGeometry world = flatten(scene);
        gbuffer = renderGBuffer(world, scene.camera, raster::SimdLevel::Scalar);
        frame = LightFrame::towards(glm::dvec3(scene.lights[0].direction));
    }
    const Light& sun() const { return scene.lights[0]; }
};

// A clipmap small enough to test quickly: 4096 texels in pages of 64, levels -6..8 (a
// texel of 8 um to 0.12 m, around the 160 x 100 view's pixels of 2 to 10 cm).
ClipmapSettings smallClipmap() { return {.resolution = 4096, .pageTexels = 64, .firstLevel = -6, .lastLevel = 8}; }

std::vector<LevelWindow> windowsAround(const ClipmapSettings& c, const LightFrame& frame, const glm::vec3& eye) {
    std::vector<LevelWindow> windows;
    for (int l = c.firstLevel; l <= c.lastLevel; ++l) windows.push_back(placeLevel(c, l, frame.local(glm::dvec3(eye))));
    return windows;
}

struct Marked {
    std::vector<PixelLevel> levels;
    KeySet requested;
};

// One frame's marking into `table`, and the set of pages it requested.
Marked mark(const SunView& view, const ClipmapSettings& c, const MarkingSettings& m, PageTable& table) {
    table.beginFrame(windowsAround(c, view.frame, view.scene.camera.eye));
    Marked out;
    markPages(view.gbuffer, view.scene.camera, view.sun(), view.frame, c, m, table, out.levels);
    for (const LevelWindow& w : table.windows())
        for (int32_t y = w.firstY; y < w.firstY + c.pagesPerSide(); ++y)
            for (int32_t x = w.firstX; x < w.firstX + c.pagesPerSide(); ++x)
                if (table.requested({w.level, x, y})) out.requested.insert({w.level, x, y});
    return out;
}

KeySet rendered(PageTable& table) {
    KeySet keys;
    for (const PageKey& k : table.allocate()) {
        keys.insert({k.level, k.x, k.y});
        table.markRendered(k);
    }
    return keys;
}

}  // namespace

TEST_CASE("virtual pages: every texel a lookup reads lies in a marked page that gets memory") {
    const SunView view;
    const ClipmapSettings c = smallClipmap();
    for (double reach : {0.0, 0.5, 1.5, 3.0}) {
        INFO("reach " << reach << " texels");
        PageTable table(c, 4096);
        const Marked marked = mark(view, c, {.lodBias = 0, .reachTexels = reach}, table);
        table.allocate();
        CHECK(table.overflowPages() == 0);
        size_t checkedPixels = 0, misses = 0;
        for (const PixelLevel& p : marked.levels) {
            if (p.level == kNoLevel) continue;
            ++checkedPixels;
            const int level = c.firstLevel + p.level;
            // Every texel of the box, by texel index, not by page arithmetic.
            for (int ty = int(std::floor(p.texel.y - reach)); ty <= int(std::floor(p.texel.y + reach)); ++ty)
                for (int tx = int(std::floor(p.texel.x - reach)); tx <= int(std::floor(p.texel.x + reach)); ++tx) {
                    const PageKey key{level, int32_t(std::floor(tx / double(c.pageTexels))),
                                      int32_t(std::floor(ty / double(c.pageTexels)))};
                    misses += table.physical(key) == kNoPhysicalPage;
                }
        }
        CHECK(checkedPixels > 10000);
        CHECK(misses == 0);
    }
}

TEST_CASE("virtual pages: every texel a PCF lookup reads, with its bias, lies in a page marking marked") {
    // The lookup's own taps (pcfLitFraction on mapReceiver's texel, as lookUpPages takes
    // them) checked against the table, for each filter and for the normal offset, which moves
    // the receiver's texel: marking's reach is lookupReachTexels, the lookup's the taps.
    const SunView view;
    const ClipmapSettings c = smallClipmap();
    const std::vector<DepthMap> maps = levelMaps(view.frame, c, {0.0, 100.0});
    FilterSettings grid4{FilterKind::Grid}, poisson{FilterKind::Poisson};
    grid4.gridSize = 4, poisson.poissonRadiusTexels = 2.5;
    BiasSettings normalOffset{.mode = BiasMode::NormalOffset};
    normalOffset.normalOffsetTexels = 2.0;
    for (const BiasSettings& bias : {BiasSettings{}, normalOffset}) {
        for (const FilterSettings& filter : {FilterSettings{}, FilterSettings{FilterKind::Bilinear}, grid4, poisson}) {
            INFO("filter " << int(filter.kind) << ", bias " << int(bias.mode));
            const PcfKernel kernel = makePcfKernel(filter);
            PageTable table(c, 4096);
            const Marked marked = mark(view, c, {.lodBias = 0, .reachTexels = lookupReachTexels(bias, filter)}, table);
            table.allocate();
            REQUIRE(table.overflowPages() == 0);
            size_t taps = 0, misses = 0;
            for (size_t k = 0; k < marked.levels.size(); ++k) {
                const PixelLevel& p = marked.levels[k];
                if (p.level == kNoLevel) continue;
                const int level = c.firstLevel + p.level;
                const MapReceiver r = mapReceiver(maps[size_t(p.level)], glm::dvec3(view.gbuffer.position[k]),
                                                  glm::dvec3(view.gbuffer.normal[k]),
                                                  glm::normalize(glm::dvec3(view.sun().direction)), bias);
                pcfLitFraction(kernel, r.texel, poissonRotationCosSin(poissonRotationIndex(k)), [&](int x, int y) {
                    const PageKey key{level, int32_t(std::floor(x / double(c.pageTexels))),
                                      int32_t(std::floor(y / double(c.pageTexels)))};
                    ++taps, misses += table.physical(key) == kNoPhysicalPage;
                    return true;
                });
            }
            CHECK(taps > 10000);
            CHECK(misses == 0);
        }
    }
    // Without the reach (the hard lookup's box for a 4 x 4 grid) taps do leave the pages.
    const PcfKernel kernel = makePcfKernel(grid4);
    PageTable table(c, 4096);
    const Marked marked = mark(view, c, {.lodBias = 0, .reachTexels = 0.0}, table);
    table.allocate();
    size_t misses = 0;
    for (const PixelLevel& p : marked.levels) {
        if (p.level == kNoLevel) continue;
        pcfLitFraction(kernel, p.texel, {1.0, 0.0}, [&](int x, int y) {
            misses += table.physical({c.firstLevel + p.level, int32_t(std::floor(x / double(c.pageTexels))),
                                      int32_t(std::floor(y / double(c.pageTexels)))}) == kNoPhysicalPage;
            return true;
        });
    }
    CHECK(misses > 0);
}

TEST_CASE("virtual pages: a pixel's level matches its footprint, the finer for a negative bias") {
    const SunView view;
    const ClipmapSettings c = smallClipmap();
    PageTable table(c, 4096);
    const Marked base = mark(view, c, {}, table);
    const Marked finer = mark(view, c, {.lodBias = -1}, table);
    size_t compared = 0, matched = 0;
    for (size_t k = 0; k < base.levels.size(); ++k) {
        if (base.levels[k].level == kNoLevel || finer.levels[k].level == kNoLevel) continue;
        ++compared;
        CHECK(finer.levels[k].level <= base.levels[k].level);
        // A texel no larger than the pixel: the level's texel is within a factor 2 of it.
        const glm::dvec3 P(view.gbuffer.position[k]);
        const double depth = glm::dot(P - glm::dvec3(view.scene.camera.eye),
                                      glm::normalize(glm::dvec3(view.scene.camera.target - view.scene.camera.eye)));
        const double footprint = depth * 2.0 * std::tan(glm::radians(double(view.scene.camera.fovyDeg)) / 2.0) /
                                 double(view.scene.camera.height);
        // The level's texel is no larger than the footprint, and the next finer one's smaller,
        // unless the window pushed the pixel coarser (near its edge) or a clamp held it.
        const double texel = c.texelM(c.firstLevel + base.levels[k].level);
        matched += texel <= footprint * (1.0 + 1e-9) && 2.0 * texel > footprint * (1.0 - 1e-9);
    }
    CHECK(matched >= compared * 99 / 100);
    CHECK(compared > 10000);
}

TEST_CASE("virtual pages: a still frame after a first one renders no page") {
    const SunView view;
    const ClipmapSettings c = smallClipmap();
    PageTable table(c, 4096);
    mark(view, c, {.reachTexels = 1.5}, table);
    const KeySet first = rendered(table);
    CHECK(first.size() > 10);
    mark(view, c, {.reachTexels = 1.5}, table);
    CHECK(rendered(table).empty());
    CHECK(table.evictedPages() == 0);
}

TEST_CASE("virtual pages: a sub-page camera move keeps every page both frames need") {
    const ClipmapSettings c = smallClipmap();
    PageTable table(c, 4096);
    const SunView before;
    const Marked a = mark(before, c, {.reachTexels = 1.5}, table);
    rendered(table);
    // 3 mm: far below a page of every level but the finest few, whose windows may shift.
    const SunView after(glm::vec3(0.003f, 0.0f, 0.002f));
    const Marked b = mark(after, c, {.reachTexels = 1.5}, table);
    const KeySet renderedNow = rendered(table);
    // Rendered now: exactly the pages the second frame needs that the first did not.
    KeySet onlyNew;
    for (const auto& key : b.requested)
        if (!a.requested.contains(key)) onlyNew.insert(key);
    CHECK(renderedNow == onlyNew);
    CHECK(renderedNow.size() < b.requested.size() / 4);
}

TEST_CASE("virtual pages: eviction takes the least recently requested page, never one requested this frame") {
    const ClipmapSettings c = smallClipmap();
    const LightFrame frame;
    std::vector<LevelWindow> windows;
    for (int l = c.firstLevel; l <= c.lastLevel; ++l) windows.push_back({l, 0, 0});
    PageTable table(c, 6);
    const auto frameOf = [&](const std::vector<PageKey>& keys) {
        table.beginFrame(windows);
        for (const PageKey& k : keys) table.request(k);
        for (const PageKey& k : table.allocate()) table.markRendered(k);
    };
    frameOf({{0, 0, 0}, {0, 1, 0}, {0, 2, 0}});   // frame 1
    frameOf({{0, 3, 0}, {0, 4, 0}});              // frame 2
    frameOf({{0, 0, 0}, {0, 5, 0}});              // frame 3: the pool is full now
    CHECK(table.residentPages() == 6);
    // Frame 4 needs three new pages: the least recently requested go, (1,0) and (2,0) from
    // frame 1, then (3,0) from frame 2 (lowest physical page on the tie with (4,0)).
    frameOf({{0, 0, 0}, {0, 5, 0}, {0, 6, 0}, {0, 7, 0}, {0, 8, 0}});
    CHECK(table.evictedPages() == 3);
    CHECK(table.evictedThisFrame() == std::vector<PageKey>{{0, 1, 0}, {0, 2, 0}, {0, 3, 0}});   // the debug table's list
    CHECK(table.overflowPages() == 0);
    for (int32_t x : {0, 5, 6, 7, 8}) CHECK(table.valid({0, x, 0}));
    for (int32_t x : {1, 2, 3}) CHECK(table.physical({0, x, 0}) == kNoPhysicalPage);
    CHECK(table.valid({0, 4, 0}));
    // More pages requested than the pool has: the excess finds no memory, and not one
    // requested page loses its memory to another.
    frameOf({{0, 0, 0}, {0, 5, 0}, {0, 6, 0}, {0, 7, 0}, {0, 8, 0}, {0, 9, 0}, {0, 10, 0}, {0, 11, 0}});
    CHECK(table.overflowPages() == 2);
    for (int32_t x : {0, 5, 6, 7, 8}) CHECK(table.valid({0, x, 0}));
    CHECK(table.residentPages() == 6);
}

TEST_CASE("virtual pages: coarse levels get memory first when the pool is short") {
    const ClipmapSettings c = smallClipmap();
    std::vector<LevelWindow> windows;
    for (int l = c.firstLevel; l <= c.lastLevel; ++l) windows.push_back({l, 0, 0});
    PageTable table(c, 2);
    table.beginFrame(windows);
    table.request({c.firstLevel, 0, 0});
    table.request({0, 0, 0});
    table.request({c.lastLevel, 0, 0});
    table.allocate();
    CHECK(table.overflowPages() == 1);
    CHECK(table.physical({c.lastLevel, 0, 0}) != kNoPhysicalPage);
    CHECK(table.physical({0, 0, 0}) != kNoPhysicalPage);
    CHECK(table.physical({c.firstLevel, 0, 0}) == kNoPhysicalPage);
}

TEST_CASE("virtual pages: a moved box invalidates exactly the pages a brute-force overlap finds") {
    const SunView view;
    const ClipmapSettings c = smallClipmap();
    PageTable table(c, 8192);
    mark(view, c, {.reachTexels = 1.5}, table);
    const KeySet all = rendered(table);
    // The box of a caster before and after a move.
    const Aabb before{{-0.6, 0.0, -0.6}, {0.6, 1.2, 0.6}}, after{{0.4, 0.0, -0.6}, {1.6, 1.2, 0.6}};
    const int invalidated = invalidateUnder({before, after}, view.frame, c, table);
    // Brute force: a page is under a box if the page's square in the light's plane (the
    // frame's x and -y, scaled by the page side) meets the rectangle of the box's corners.
    const auto under = [&](const Aabb& box, int level, int32_t px, int32_t py) {
        glm::dvec2 lo(1e300), hi(-1e300);
        for (int k = 0; k < 8; ++k) {
            const glm::dvec3 P{k & 1 ? box.max.x : box.min.x, k & 2 ? box.max.y : box.min.y, k & 4 ? box.max.z : box.min.z};
            const glm::dvec3 l = view.frame.local(P);
            lo = glm::min(lo, glm::dvec2(l.x, -l.y)), hi = glm::max(hi, glm::dvec2(l.x, -l.y));
        }
        const double side = c.pageM(level);
        return px * side <= hi.x && (px + 1) * side > lo.x && py * side <= hi.y && (py + 1) * side > lo.y;
    };
    size_t expected = 0;
    for (const auto& [level, px, py] : all) {
        const bool hit = under(before, level, px, py) || under(after, level, px, py);
        expected += hit;
        CHECK(table.valid({level, px, py}) == !hit);
    }
    CHECK(size_t(invalidated) == expected);
    CHECK(expected > 0);
    CHECK(expected < all.size());
    // The next frame renders those pages again, and only those.
    mark(view, c, {.reachTexels = 1.5}, table);
    CHECK(rendered(table).size() == expected);
}

TEST_CASE("virtual pages: marking is the same on 1 and 2 threads") {
    const SunView view;
    const ClipmapSettings c = smallClipmap();
    const auto run = [&](int threads) {
        PageTable table(c, 4096);
        return withThreads(threads, [&] { return mark(view, c, {.reachTexels = 1.5}, table); });
    };
    const Marked one = run(1), two = run(2);
    CHECK(one.requested == two.requested);
    REQUIRE(one.levels.size() == two.levels.size());
    for (size_t k = 0; k < one.levels.size(); ++k) {
        CHECK(one.levels[k].level == two.levels[k].level);
        CHECK(one.levels[k].texel == two.levels[k].texel);
    }
}

TEST_CASE("virtual pages: settings outside their ranges are refused") {
    CHECK_THROWS_AS(checkClipmapSettings({.resolution = 3000}), std::invalid_argument);
    CHECK_THROWS_AS(checkClipmapSettings({.resolution = 4096, .pageTexels = 4}), std::invalid_argument);
    CHECK_THROWS_AS(checkClipmapSettings({.resolution = 4096, .pageTexels = 4096}), std::invalid_argument);
    CHECK_THROWS_AS(checkClipmapSettings({.firstLevel = 3, .lastLevel = 2}), std::invalid_argument);
    CHECK_THROWS_AS(PageTable(smallClipmap(), 0), std::invalid_argument);
    CHECK(pageOf(-1e300, 64) == -(1 << 30));
    CHECK(pageOf(1e300, 64) == (1 << 30));
    CHECK(pageOf(-0.5, 64) == -1);
    CHECK(pageOf(63.99, 64) == 0);
}
