// Regressions from review: non-finite clip coordinates, bin memory grouping, clipped
// triangles independent of vertex rotation, and the polygon offset taken per primitive.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "tests/raster/raster_test_util.h"
#include "tests/same_bits.h"

using namespace shadowlab;
using namespace shadowlab::raster;

TEST_CASE("a clip coordinate that overflows to infinity drops the triangle, never garbage") {
    // x_clip = 1e30 x - 1 overflows to -inf for x = -1e10 while w stays 1.
    Framebuffer fb(64, 64, {.stencil = true});
    glm::mat4 m = test::clipFromWindow(64, 64);
    m[0][0] = 1e30f;
    const std::vector<glm::vec3> p = {{-1e10f, 0, 0.5f}, {1.25e-30f, 0, 0.5f}, {1.25e-30f, 16, 0.5f}};
    const std::vector<glm::uvec3> t = {{0, 1, 2}};
    DrawCall call = test::windowDraw(fb, p, t);
    call.clipFromObject = m;
    for (SimdLevel level : test::supportedLevels()) {
        Rasterizer r(level);
        r.draw(fb, test::countingState(), call);
        int covered = 0;
        for (uint8_t c : fb.stencilImage()) covered += c;
        CHECK(covered == 0);
    }
    // The same with +inf depth and the far plane off (an infinite projection).
    PipelineState s = test::countingState();
    s.clipFar = false;
    glm::mat4 deep = test::clipFromWindow(64, 64);
    deep[2][2] = 1e38f;
    const std::vector<glm::vec3> q = {{1, 1, 1e10f}, {30, 1, 0.5f}, {1, 30, 0.5f}};
    DrawCall far = test::windowDraw(fb, q, t);
    far.clipFromObject = deep;
    Framebuffer fb2(64, 64, {.stencil = true});
    Rasterizer().draw(fb2, s, far);
    int covered = 0;
    for (uint8_t c : fb2.stencilImage()) covered += c;
    CHECK(covered == 0);
}

TEST_CASE("binning in groups under a tiny entry budget gives the same bytes as one group") {
    // 20000 triangles (5 chunks) of all sizes over 12 tiles; budget 1 forces one chunk per group.
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> u(-40.0f, 300.0f), z(0.0f, 1.0f);
    std::vector<glm::vec3> p;
    std::vector<glm::uvec3> t;
    for (uint32_t k = 0; k < 20000; ++k) {
        for (int c = 0; c < 3; ++c) p.push_back({u(rng), u(rng) * 0.75f, z(rng)});
        t.push_back({3 * k, 3 * k + 1, 3 * k + 2});
    }
    PipelineState s;
    s.cull = CullMode::None;
    s.output = FragmentOutput::PrimitiveId;
    Framebuffer a(256, 192, {.primitiveId = true}), b(256, 192, {.primitiveId = true});
    Rasterizer whole, grouped(bestSimdLevel(), 1);
    whole.draw(a, s, test::windowDraw(a, p, t));
    grouped.draw(b, s, test::windowDraw(b, p, t));
    CHECK(whole.stats().binEntries == grouped.stats().binEntries);
    const auto ia = a.primitiveIdImage(), ib = b.primitiveIdImage();
    const auto da = a.depthImage(), db = b.depthImage();
    CHECK(test::sameBytes(ia, ib));
    CHECK(test::sameBytes(da, db));
}

TEST_CASE("a near-clipped triangle gives the same depth bits however its indices are rotated or numbered") {
    std::mt19937 rng(21);
    std::uniform_real_distribution<float> xy(-3.0f, 3.0f), zz(-6.0f, 2.0f);
    const glm::mat4 proj = glm::perspective(1.0f, 4.0f / 3.0f, 0.5f, 40.0f);
    int clipped = 0;
    for (int trial = 0; trial < 100; ++trial) {
        const std::vector<glm::vec3> p = {{xy(rng), xy(rng), zz(rng)}, {xy(rng), xy(rng), zz(rng)}, {xy(rng), xy(rng), zz(rng)}};
        // Rotations 0..2 of the indices into p, and rotation 3: the same triangle stored in
        // reverse vertex order (so its indices rank differently), drawn as (2, 1, 0).
        const std::vector<glm::vec3> reversed = {p[2], p[1], p[0]};
        std::vector<float> depth[4];
        for (int rotation = 0; rotation < 4; ++rotation) {
            const std::vector<glm::uvec3> t = {rotation == 3 ? glm::uvec3(2, 1, 0)
                                                             : glm::uvec3(rotation, (rotation + 1) % 3, (rotation + 2) % 3)};
            Framebuffer fb(256, 192);
            PipelineState s;
            s.cull = CullMode::None;
            s.offset = {1.0f, 4.0f};
            DrawCall call;
            call.vertices.positions = rotation == 3 ? reversed : p;
            call.triangles = t;
            call.clipFromObject = proj;
            Rasterizer r;
            r.draw(fb, s, call);
            clipped += rotation == 0 && r.stats().trianglesClipped == 1;
            depth[rotation] = fb.depthImage();
        }
        INFO("trial " << trial);
        CHECK(test::sameBytes(depth[0], depth[1]));
        CHECK(test::sameBytes(depth[0], depth[2]));
        CHECK(test::sameBytes(depth[0], depth[3]));
    }
    CHECK(clipped > 30);
}

TEST_CASE("polygon offset units use the largest depth of the whole clipped primitive") {
    // A ground triangle cut by the near plane into the quad [B, C, I_CA, I_AB], fanned from
    // B (index 0, 0.8 m away, window depth 0.38): the fan triangle (B, I_CA, I_AB) lies
    // wholly below depth 0.5, but the primitive reaches C (30 m, depth 0.996), so both
    // fan triangles must get r = 2^-24 rather than 2^-25 for the shallow one.
    const std::vector<glm::vec3> p = {{6.0f, -0.2f, -0.8f}, {-6.0f, -0.2f, -30.0f}, {0.0f, -0.2f, 1.0f}};
    const std::vector<glm::uvec3> t = {{0, 1, 2}};
    DrawCall call;
    call.vertices.positions = p;
    call.triangles = t;
    call.clipFromObject = glm::perspective(1.0f, 4.0f / 3.0f, 0.5f, 40.0f);
    PipelineState s;
    s.cull = CullMode::None;
    Framebuffer plain(128, 96), offset(128, 96);
    Rasterizer r;
    r.draw(plain, s, call);
    CHECK(r.stats().trianglesClipped == 1);
    s.offset = {0.0f, 1000.0f};
    r.draw(offset, s, call);
    const auto a = plain.depthImage(), b = offset.depthImage();
    const double expected = 1000.0 * std::ldexp(1.0, -24);
    int checked = 0, shallow = 0, wrong = 0;
    for (size_t k = 0; k < a.size(); ++k) {
        if (a[k] == 1.0f || b[k] == 1.0f) continue;
        wrong += std::abs(double(b[k]) - double(a[k]) - expected) > 0.01 * expected;
        shallow += a[k] < 0.45f;
        ++checked;
    }
    CHECK(checked > 1000);
    CHECK(shallow > 100);
    CHECK(wrong == 0);
}
