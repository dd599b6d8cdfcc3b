// Coverage: the top-left fill rule, exactly-once coverage of fans and closed meshes,
// sub-pixel precision, degenerate triangles, and huge and tiny coordinates.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <numeric>
#include <random>

#include "tests/raster/raster_test_util.h"

using namespace shadowlab;
using namespace shadowlab::raster;
using shadowlab::test::countingState;
using shadowlab::test::oracleCovers;
using shadowlab::test::supportedLevels;
using shadowlab::test::windowDraw;

namespace {

std::vector<uint8_t> countCoverage(SimdLevel level, int size, const std::vector<glm::vec3>& positions,
                                   const std::vector<glm::uvec3>& triangles) {
    Framebuffer fb(size, size, {.stencil = true});
    Rasterizer r(level);
    r.draw(fb, countingState(), windowDraw(fb, positions, triangles));
    std::vector<uint8_t> count = fb.stencilImage();
    // The rasterizer's fragment count (the fill) is the same coverage, summed (no count
    // here comes near the stencil's wrap at 256).
    CHECK(r.stats().fragments == std::accumulate(count.begin(), count.end(), uint64_t(0)));
    return count;
}

// A random position on the 1/256 grid, often exactly on a pixel centre or a pixel corner
// so that edges pass through centres and the fill rule matters.
glm::vec3 randomVertex(std::mt19937& rng, float extent) {
    std::uniform_int_distribution<int> coord(0, int(extent * 256.0f));
    std::uniform_int_distribution<int> kind(0, 2);
    auto pick = [&] {
        const int sub = coord(rng);
        switch (kind(rng)) {
            case 0: return float(sub / 256) + 0.5f;   // a pixel centre
            case 1: return float(sub / 128) * 0.5f;   // a centre or a corner
            default: return float(sub) / 256.0f;
        }
    };
    const float x = pick(), y = pick();
    return {x, y, 0.5f};
}

}  // namespace

TEST_CASE("each triangle covers exactly the pixel centres the fill-rule oracle gives") {
    std::mt19937 rng(7);
    constexpr int kSize = 64;
    for (SimdLevel level : supportedLevels()) {
        for (int trial = 0; trial < 300; ++trial) {
            const std::vector<glm::vec3> p = {randomVertex(rng, kSize), randomVertex(rng, kSize), randomVertex(rng, kSize)};
            const std::vector<uint8_t> count = countCoverage(level, kSize, p, {{0, 1, 2}});
            const glm::i64vec2 v[3] = {test::snap(p[0]), test::snap(p[1]), test::snap(p[2])};
            int mismatches = 0;
            for (int j = 0; j < kSize; ++j) {
                for (int i = 0; i < kSize; ++i) mismatches += count[size_t(j * kSize + i)] != (oracleCovers(v, i, j) ? 1 : 0);
            }
            INFO("level " << simdLevelName(level) << " trial " << trial);
            REQUIRE(mismatches == 0);
        }
    }
}

TEST_CASE("a triangle fan covers every pixel centre inside it exactly once") {
    std::mt19937 rng(11);
    constexpr int kSize = 128;
    for (int trial = 0; trial < 40; ++trial) {
        // Spokes at increasing angles around a centre that sits on a pixel centre.
        const glm::vec3 centre(64.5f, 64.5f, 0.5f);
        std::vector<glm::vec3> p = {centre};
        const int spokes = 3 + trial % 13;
        std::uniform_real_distribution<float> radius(8.0f, 60.0f);
        for (int s = 0; s < spokes; ++s) {
            const double angle = 2.0 * M_PI * (s + 0.5 * (trial % 2)) / spokes;
            const float r = radius(rng);
            // Snap to the pixel-centre lattice every other spoke: edges then pass through centres.
            glm::vec3 q(centre.x + r * float(std::cos(angle)), centre.y + r * float(std::sin(angle)), 0.5f);
            if (s % 2 == 0) q = glm::vec3(std::floor(q.x) + 0.5f, std::floor(q.y) + 0.5f, 0.5f);
            p.push_back(q);
        }
        std::vector<glm::uvec3> tris;
        for (int s = 0; s < spokes; ++s) tris.push_back({0u, uint32_t(1 + s), uint32_t(1 + (s + 1) % spokes)});
        for (SimdLevel level : supportedLevels()) {
            const std::vector<uint8_t> count = countCoverage(level, kSize, p, tris);
            int twice = 0, holes = 0;
            for (int j = 0; j < kSize; ++j) {
                for (int i = 0; i < kSize; ++i) {
                    const uint8_t c = count[size_t(j * kSize + i)];
                    twice += c > 1;
                    // A centre inside the fan polygon (not on its outer boundary) must be covered.
                    const glm::i64vec2 centreSub = test::snap(centre);
                    bool inside = false;
                    for (int s = 0; s < spokes && !inside; ++s) {
                        const glm::i64vec2 v[3] = {centreSub, test::snap(p[size_t(1 + s)]), test::snap(p[size_t(1 + (s + 1) % spokes)])};
                        inside = oracleCovers(v, i, j);
                    }
                    holes += inside && c == 0;
                }
            }
            INFO("trial " << trial << " level " << simdLevelName(level));
            CHECK(twice == 0);
            CHECK(holes == 0);
        }
    }
}

TEST_CASE("a closed mesh is watertight: front and back coverage cancel at every pixel") {
    // A UV sphere projected in perspective: every pixel centre inside the silhouette is
    // covered once by a front face and once by a back face; counting front +1 and back -1
    // (the shadow-volume invariant) must leave exactly 0 everywhere.
    const int slices = 37, stacks = 23;
    std::vector<glm::vec3> p;
    std::vector<glm::uvec3> t;
    for (int s = 0; s <= stacks; ++s) {
        for (int k = 0; k < slices; ++k) {
            const double theta = M_PI * s / stacks, phi = 2.0 * M_PI * k / slices;
            p.push_back(glm::vec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)));
        }
    }
    auto at = [&](int s, int k) { return uint32_t(s * slices + (k % slices)); };
    for (int s = 0; s < stacks; ++s) {
        for (int k = 0; k < slices; ++k) {
            if (s > 0) t.push_back({at(s, k), at(s, k + 1), at(s + 1, k)});
            if (s + 1 < stacks) t.push_back({at(s, k + 1), at(s + 1, k + 1), at(s + 1, k)});
        }
    }
    glm::mat4 view(1.0f);
    view[3] = glm::vec4(0.13f, -0.07f, -2.7f, 1.0f);
    const float f = 1.0f / std::tan(0.5f * 0.9f), n = 0.1f, fa = 10.0f;
    glm::mat4 proj(0.0f);
    proj[0][0] = f, proj[1][1] = f, proj[2][2] = (fa + n) / (n - fa), proj[2][3] = -1.0f, proj[3][2] = 2 * fa * n / (n - fa);
    for (SimdLevel level : supportedLevels()) {
        Framebuffer fb(200, 150, {.stencil = true});
        PipelineState s;
        s.cull = CullMode::None;
        s.depth.test = false;
        s.stencil.enabled = true;
        s.stencil.front.depthPass = StencilOp::IncrementWrap;
        s.stencil.back.depthPass = StencilOp::DecrementWrap;
        DrawCall call;
        call.vertices.positions = p;
        call.triangles = t;
        call.clipFromObject = proj * view;
        Rasterizer r(level);
        r.draw(fb, s, call);
        const auto balance = fb.stencilImage();
        int nonZero = 0;
        for (uint8_t b : balance) nonZero += b != 0;
        CHECK(nonZero == 0);
        // And the front faces alone cover each centre at most once, some centres at all.
        Framebuffer front(200, 150, {.stencil = true});
        PipelineState c = test::countingState();
        c.cull = CullMode::Back;
        r.draw(front, c, call);
        int covered = 0, twice = 0;
        for (uint8_t b : front.stencilImage()) covered += b == 1, twice += b > 1;
        CHECK(twice == 0);
        CHECK(covered > 5000);
    }
}

TEST_CASE("sub-pixel precision: moving a vertex by 1/256 pixel changes coverage exactly as the oracle says") {
    constexpr int kSize = 16;
    for (int step = 0; step < 512; ++step) {
        const float dx = float(step) / 256.0f;
        const std::vector<glm::vec3> p = {{3.0f + dx, 2.5f, 0.5f}, {12.5f, 7.25f + dx / 3.0f, 0.5f}, {4.5f, 13.5f, 0.5f}};
        const glm::i64vec2 v[3] = {test::snap(p[0]), test::snap(p[1]), test::snap(p[2])};
        const auto count = countCoverage(bestSimdLevel(), kSize, p, {{0, 1, 2}});
        int mismatches = 0;
        for (int j = 0; j < kSize; ++j) {
            for (int i = 0; i < kSize; ++i) mismatches += count[size_t(j * kSize + i)] != (oracleCovers(v, i, j) ? 1 : 0);
        }
        INFO("step " << step);
        REQUIRE(mismatches == 0);
    }
}

TEST_CASE("degenerate, zero-area and non-finite triangles draw nothing and do not crash") {
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    const std::vector<glm::vec3> p = {{1.5f, 1.5f, 0.5f}, {9.5f, 9.5f, 0.5f}, {5.5f, 5.5f, 0.5f},     // collinear
                                      {2.0f, 2.0f, 0.5f}, {2.001f, 2.0f, 0.5f}, {2.0f, 2.001f, 0.5f},  // below a sub-pixel
                                      {nan, 1.0f, 0.5f}, {inf, 3.0f, 0.5f}, {-inf, inf, 0.5f}};
    const std::vector<glm::uvec3> t = {{0, 1, 2}, {3, 3, 3}, {3, 4, 5}, {6, 1, 2}, {7, 1, 2}, {8, 1, 2}, {7, 8, 6}};
    for (SimdLevel level : supportedLevels()) {
        const auto count = countCoverage(level, 16, p, t);
        int covered = 0;
        for (uint8_t c : count) covered += c;
        CHECK(covered == 0);
    }
}

TEST_CASE("huge coordinates are clipped at the guard band and cover the right half-plane") {
    // One triangle reaching 10^7 pixels away: only its edge x = 20.3 crosses the viewport.
    constexpr int kSize = 64;
    const std::vector<glm::vec3> p = {{20.3f, -1.0e7f, 0.5f}, {20.3f, 1.0e7f, 0.5f}, {1.0e7f, 0.0f, 0.5f}};
    for (SimdLevel level : supportedLevels()) {
        const auto count = countCoverage(level, kSize, p, {{0, 1, 2}});
        int wrong = 0;
        for (int j = 0; j < kSize; ++j) {
            for (int i = 0; i < kSize; ++i) wrong += count[size_t(j * kSize + i)] != (i + 0.5 > 20.3 ? 1 : 0);
        }
        CHECK(wrong == 0);
    }
}

TEST_CASE("tiny triangles cover a centre only when they contain it") {
    constexpr int kSize = 8;
    // Width 2/256 pixel around the centre of pixel (3, 4): covered; shifted off it: not.
    const std::vector<glm::vec3> on = {{3.5f - 1 / 256.0f, 4.5f - 1 / 256.0f, 0.5f}, {3.5f + 1 / 256.0f, 4.5f - 1 / 256.0f, 0.5f}, {3.5f, 4.5f + 1 / 256.0f, 0.5f}};
    const std::vector<glm::vec3> off = {{3.6f, 4.6f, 0.5f}, {3.7f, 4.6f, 0.5f}, {3.6f, 4.7f, 0.5f}};
    for (SimdLevel level : supportedLevels()) {
        const auto a = countCoverage(level, kSize, on, {{0, 1, 2}});
        const auto b = countCoverage(level, kSize, off, {{0, 1, 2}});
        int sumA = 0, sumB = 0;
        for (uint8_t c : a) sumA += c;
        for (uint8_t c : b) sumB += c;
        CHECK(sumA == 1);
        CHECK(a[4 * kSize + 3] == 1);
        CHECK(sumB == 0);
    }
}
