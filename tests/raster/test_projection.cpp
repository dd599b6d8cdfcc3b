// Perspective: near-plane clipping, perspective-correct varyings, and outer-conservative
// coverage, each against an exact or analytic answer.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "tests/raster/raster_test_util.h"

using namespace shadowlab;
using namespace shadowlab::raster;

namespace {

constexpr int kWidth = 160, kHeight = 120;
constexpr double kFovy = 1.0, kNear = 0.5, kFar = 40.0;

glm::dmat4 projection() { return glm::perspectiveRH_NO(kFovy, double(kWidth) / kHeight, kNear, kFar); }

// View-space direction through the centre of pixel (i, j), camera at the origin looking down -z.
glm::dvec3 pixelDirection(int i, int j) {
    const double t = std::tan(kFovy / 2.0), aspect = double(kWidth) / kHeight;
    const double x = ((i + 0.5) / kWidth * 2.0 - 1.0) * t * aspect;
    const double y = (1.0 - (j + 0.5) / kHeight * 2.0) * t;
    return {x, y, -1.0};
}

}  // namespace

TEST_CASE("near-plane clipping: a ground triangle passing behind the camera") {
    // Ground y = -1 from z = +20 (behind the camera) to z = -60: the near and far planes
    // both cut it. A pixel is covered iff its ray meets the triangle between them.
    const std::vector<glm::vec3> p = {{-30.0f, -1.0f, 20.0f}, {30.0f, -1.0f, 20.0f}, {0.0f, -1.0f, -60.0f}};
    Framebuffer fb(kWidth, kHeight, {.stencil = true});
    PipelineState s = test::countingState();
    DrawCall call;
    call.vertices.positions = p;
    const std::vector<glm::uvec3> t = {{0, 1, 2}};
    call.triangles = t;
    call.clipFromObject = glm::mat4(projection());
    Rasterizer r;
    r.draw(fb, s, call);
    CHECK(r.stats().trianglesClipped == 1);
    const auto count = fb.stencilImage();
    int wrong = 0, covered = 0;
    for (int j = 0; j < kHeight; ++j) {
        for (int i = 0; i < kWidth; ++i) {
            const glm::dvec3 d = pixelDirection(i, j);
            bool expected = false, nearBoundary = false;
            if (d.y < 0.0) {
                const glm::dvec3 hit = d * (-1.0 / d.y);   // on y = -1
                const double depth = -hit.z;
                // Inside the triangle (x, z): between the two slanted edges and z < 20.
                const double halfWidth = 30.0 * (60.0 + hit.z) / 80.0;
                expected = std::abs(hit.x) < halfWidth && depth > kNear && depth < kFar;
                // Pixels whose centre ray passes within a hundredth of a pixel of a boundary are
                // not judged: the float projection may place them either side.
                const double pixelAtDepth = 2.0 * std::tan(kFovy / 2.0) * depth / kHeight;
                nearBoundary = std::abs(std::abs(hit.x) - halfWidth) < 0.01 * pixelAtDepth ||
                               std::abs(depth - kFar) < 0.05 || std::abs(depth - kNear) < 1e-3;
            }
            covered += count[size_t(j * kWidth + i)];
            if (!nearBoundary) wrong += (count[size_t(j * kWidth + i)] == 1) != expected;
        }
    }
    CHECK(wrong == 0);
    CHECK(covered > kWidth * kHeight / 3);
}

TEST_CASE("varyings are interpolated perspective-correctly") {
    // A quad on the slanted plane z = -2 - 0.5 x (view space); the varyings are the world
    // x and z of each vertex. At every covered pixel they must equal the ray-plane hit.
    const std::vector<glm::vec3> p = {{-3, -2, -0.5f}, {3, -2, -3.5f}, {3, 2, -3.5f}, {-3, 2, -0.5f}};
    const std::vector<float> varyings = {-3, -0.5f, 3, -3.5f, 3, -3.5f, -3, -0.5f};
    const std::vector<glm::uvec3> t = {{0, 1, 2}, {0, 2, 3}};
    for (SimdLevel level : {SimdLevel::Scalar, bestSimdLevel()}) {
        Framebuffer fb(kWidth, kHeight, {.color = true});
        fb.clearColor(glm::vec4(-100.0f));
        PipelineState s;
        s.cull = CullMode::None;
        s.output = FragmentOutput::VaryingColor;
        DrawCall call;
        call.vertices.positions = p;
        call.vertices.varyings = varyings;
        call.vertices.varyingCount = 2;
        call.triangles = t;
        call.clipFromObject = glm::mat4(projection());
        Rasterizer r(level);
        r.draw(fb, s, call);
        const auto x = fb.colorImage(0), z = fb.colorImage(1);
        int checked = 0;
        double worst = 0.0;
        for (int j = 0; j < kHeight; ++j) {
            for (int i = 0; i < kWidth; ++i) {
                const size_t k = size_t(j * kWidth + i);
                if (x[k] == -100.0f) continue;
                const glm::dvec3 d = pixelDirection(i, j);
                const double tHit = -2.0 / (d.z + 0.5 * d.x);   // d.z t = -2 - 0.5 d.x t
                worst = std::max({worst, std::abs(double(x[k]) - d.x * tHit), std::abs(double(z[k]) - d.z * tHit)});
                ++checked;
            }
        }
        CHECK(checked > 3000);
        CHECK(worst < 2e-4);
    }
}

TEST_CASE("conservative rasterization misses no pixel the triangle touches") {
    // Vertices off the 1/256 snapping grid (on a 1/4096 grid) so snapping error matters.
    // The exact test runs in integers of 1/4096 pixel: the closed pixel square and the
    // closed triangle intersect iff no separating axis exists among x, y and the normals.
    constexpr int kSize = 64;
    constexpr int64_t kUnit = 4096;
    std::mt19937 rng(3);
    std::uniform_int_distribution<int64_t> coord(-4 * kUnit, (kSize + 4) * kUnit);
    auto touches = [](const glm::i64vec2 v[3], int64_t x0, int64_t y0, int64_t x1, int64_t y1) {
        int64_t lo[2] = {v[0].x, v[0].y}, hi[2] = {v[0].x, v[0].y};
        for (int k = 1; k < 3; ++k) {
            lo[0] = std::min(lo[0], v[k].x), hi[0] = std::max(hi[0], v[k].x);
            lo[1] = std::min(lo[1], v[k].y), hi[1] = std::max(hi[1], v[k].y);
        }
        if (hi[0] < x0 || lo[0] > x1 || hi[1] < y0 || lo[1] > y1) return false;
        const int64_t area = (v[1].x - v[0].x) * (v[2].y - v[0].y) - (v[2].x - v[0].x) * (v[1].y - v[0].y);
        for (int k = 0; k < 3; ++k) {
            const glm::i64vec2 a = v[k], b = v[(k + 1) % 3];
            bool anyInside = false;
            for (const glm::i64vec2 c : {glm::i64vec2(x0, y0), glm::i64vec2(x1, y0), glm::i64vec2(x0, y1), glm::i64vec2(x1, y1)}) {
                const int64_t side = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
                anyInside |= area > 0 ? side >= 0 : side <= 0;
            }
            if (!anyInside) return false;
        }
        return true;
    };
    for (int trial = 0; trial < 300; ++trial) {
        glm::i64vec2 v[3];
        std::vector<glm::vec3> p;
        for (auto& q : v) {
            q = {coord(rng), coord(rng)};
            p.push_back(glm::vec3(float(q.x) / kUnit, float(q.y) / kUnit, 0.5f));
        }
        if ((v[1].x - v[0].x) * (v[2].y - v[0].y) == (v[2].x - v[0].x) * (v[1].y - v[0].y)) continue;
        Framebuffer fb(kSize, kSize, {.stencil = true});
        PipelineState s = test::countingState();
        s.conservative = true;
        Rasterizer r;
        r.draw(fb, s, test::windowDraw(fb, p, {{0, 1, 2}}));
        const auto count = fb.stencilImage();
        int missed = 0, far = 0;
        const int64_t slack = 2 * kUnit / 256;   // snapping (half a sub-pixel) and the 129/256 dilation
        for (int j = 0; j < kSize; ++j) {
            for (int i = 0; i < kSize; ++i) {
                const bool covered = count[size_t(j * kSize + i)] == 1;
                missed += !covered && touches(v, i * kUnit, j * kUnit, (i + 1) * kUnit, (j + 1) * kUnit);
                far += covered && !touches(v, i * kUnit - slack, j * kUnit - slack, (i + 1) * kUnit + slack, (j + 1) * kUnit + slack);
            }
        }
        INFO("trial " << trial);
        REQUIRE(missed == 0);
        REQUIRE(far == 0);
    }
}
