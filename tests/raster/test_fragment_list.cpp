// FragmentOutput::FragmentList: every fragment that passes the tests reaches its tile's list,
// once, with the pixel, depth and triangle it came from, in submission order per pixel; the
// lists are the same bytes at every SIMD level and thread count, and the depth test against
// an earlier opaque draw keeps only the fragments in front of it.
#include <doctest/doctest.h>

#include <map>
#include <tuple>
#include <utility>

#include "raster/thread_count.h"
#include "tests/raster/raster_test_util.h"

using namespace shadowlab;
using namespace shadowlab::test;

namespace {

// Overlapping triangles at several depths over a 150 x 130 framebuffer (three tiles
// wide, so the lists of several tiles are filled), one of them larger than a tile.
struct Layers {
    std::vector<glm::vec3> positions = {
        {3.5f, 2.25f, 0.2f}, {140.0f, 20.0f, 0.2f}, {30.0f, 125.0f, 0.2f},     // 0
        {10.0f, 10.0f, 0.5f}, {100.0f, 15.5f, 0.6f}, {60.0f, 90.0f, 0.7f},     // 1
        {80.0f, 40.0f, 0.9f}, {145.0f, 100.0f, 0.9f}, {70.0f, 128.0f, 0.1f},   // 2
    };
    std::vector<glm::uvec3> triangles = {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}};
};

struct Drawn {
    std::vector<raster::Fragment> fragments;   // tile by tile, each tile's in drawing order
    uint64_t covered = 0;
};

raster::PipelineState listState(bool depthTest) {
    raster::PipelineState s;
    s.cull = raster::CullMode::None;
    s.depth.test = depthTest;
    s.depth.write = false;
    s.output = raster::FragmentOutput::FragmentList;
    return s;
}

// The translucent layers' fragments, optionally behind an opaque square at depth 0.55.
Drawn drawLists(raster::SimdLevel level, bool opaqueFirst) {
    raster::Framebuffer fb(150, 130, {.fragments = true});
    raster::Rasterizer rasterizer(level);
    if (opaqueFirst) {
        const std::vector<glm::vec3> square = {{40, 30, 0.55f}, {120, 30, 0.55f}, {120, 110, 0.55f}, {40, 110, 0.55f}};
        const std::vector<glm::uvec3> halves = {{0, 1, 2}, {0, 2, 3}};
        raster::PipelineState opaque;
        opaque.cull = raster::CullMode::None;
        rasterizer.draw(fb, opaque, windowDraw(fb, square, halves));
    }
    const Layers layers;
    rasterizer.resetStats();
    rasterizer.draw(fb, listState(opaqueFirst), windowDraw(fb, layers.positions, layers.triangles));
    Drawn drawn;
    drawn.covered = rasterizer.stats().fragments;
    for (int tile = 0; tile < fb.tilesX() * fb.tilesY(); ++tile) {
        for (const raster::Fragment& f : fb.tileFragments(tile)) drawn.fragments.push_back(f);
    }
    return drawn;
}

}  // namespace

namespace shadowlab::raster {
bool operator==(const Fragment& a, const Fragment& b) {
    return a.pixel == b.pixel && a.depth == b.depth && a.primitiveId == b.primitiveId;
}
}  // namespace shadowlab::raster

TEST_CASE("a fragment list holds every covered fragment once, each pixel's in submission order") {
    const Drawn drawn = drawLists(raster::SimdLevel::Scalar, false);
    REQUIRE(drawn.fragments.size() == drawn.covered);   // no test, so every covered fragment
    const Layers layers;
    raster::Framebuffer fb(150, 130);
    std::map<std::pair<uint32_t, uint32_t>, int> seen;   // (pixel, triangle) -> count
    std::map<uint32_t, uint32_t> lastTriangle;
    for (const raster::Fragment& f : drawn.fragments) {
        ++seen[{f.pixel, f.primitiveId}];
        if (lastTriangle.count(f.pixel)) CHECK(f.primitiveId > lastTriangle[f.pixel]);
        lastTriangle[f.pixel] = f.primitiveId;
    }
    // Against the coverage oracle, pixel by pixel and triangle by triangle.
    uint64_t expected = 0;
    for (uint32_t t = 0; t < layers.triangles.size(); ++t) {
        const glm::i64vec2 v[3] = {snap(layers.positions[layers.triangles[t].x]), snap(layers.positions[layers.triangles[t].y]),
                                   snap(layers.positions[layers.triangles[t].z])};
        for (int j = 0; j < fb.height(); ++j) {
            for (int i = 0; i < fb.width(); ++i) {
                const bool covered = oracleCovers(v, i, j);
                expected += covered;
                const auto found = seen.find({uint32_t(fb.index(i, j)), t});
                CHECK((found != seen.end() && found->second == 1) == covered);
            }
        }
    }
    CHECK(drawn.fragments.size() == expected);
    // Triangle 0 lies at depth 0.2 everywhere (up to the rounding of the clip transform).
    for (const raster::Fragment& f : drawn.fragments) {
        if (f.primitiveId == 0) CHECK(f.depth == doctest::Approx(0.2).epsilon(1e-6));
    }
}

TEST_CASE("the depth test against an opaque draw keeps only the fragments in front of it") {
    const Drawn all = drawLists(raster::SimdLevel::Scalar, false);
    const Drawn front = drawLists(raster::SimdLevel::Scalar, true);
    raster::Framebuffer fb(150, 130);
    size_t hidden = 0;
    for (const raster::Fragment& f : all.fragments) {
        bool underSquare = false;
        for (int j = 30; j < 110 && !underSquare; ++j) {
            for (int i = 40; i < 120 && !underSquare; ++i) underSquare = fb.index(i, j) == f.pixel;
        }
        hidden += underSquare && f.depth >= 0.55f;
    }
    REQUIRE(hidden > 1000);
    CHECK(front.fragments.size() == all.fragments.size() - hidden);
    for (const raster::Fragment& f : front.fragments) CHECK(f.depth < 1.0f);
}

TEST_CASE("fragment lists are the same bytes at every SIMD level and on 1, 2 and 8 threads") {
    const Drawn scalar = withThreads(1, [] { return drawLists(raster::SimdLevel::Scalar, true); });
    for (raster::SimdLevel level : supportedLevels()) {
        for (int threads : {1, 2, 8}) {
            CAPTURE(threads);
            const Drawn other = withThreads(threads, [&] { return drawLists(level, true); });
            CHECK(other.fragments == scalar.fragments);
        }
    }
}

TEST_CASE("fragment-list output needs a framebuffer with fragment lists") {
    raster::Framebuffer fb(64, 64);
    raster::Rasterizer rasterizer(raster::SimdLevel::Scalar);
    const Layers layers;
    CHECK_THROWS_WITH_AS(rasterizer.draw(fb, listState(false), windowDraw(fb, layers.positions, layers.triangles)),
                         "draw: fragment-list output on a framebuffer without fragment lists", std::invalid_argument);
    CHECK_THROWS_AS(fb.tileFragments(0), std::logic_error);
}
