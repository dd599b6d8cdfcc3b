// Triangle setup's kernel (raster/setup_triangles.inl): every SIMD level gives the scalar
// build's bytes, and the double-precision lanes give the integers and planes that plain
// int64 arithmetic and frexp/ldexp give (the claim "exact in double" of the kernel).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include "raster/setup.h"
#include "raster/tile_kernels.h"
#include "raster_test_util.h"

using namespace shadowlab;
using namespace shadowlab::raster;

namespace {

constexpr int kViewportWidth = 1024, kViewportHeight = 768;

// A mix of triangles: a few pixels wide, huge (up to the guard band's 2^22 sub-pixels),
// degenerate (two equal corners, or collinear), with depths including 0 and subnormals.
SetupBatch randomBatch(std::mt19937& rng, int count, int varyings) {
    SetupBatch batch{};
    std::uniform_int_distribution<int32_t> anywhere(-(1 << 22) + 1, (1 << 22) - 1), local(-2048, 2048 * 128);
    std::uniform_int_distribution<int> kind(0, 5);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int t = 0; t < count; ++t) {
        const int k = kind(rng);
        const int32_t baseX = local(rng), baseY = local(rng);
        for (int c = 0; c < 3; ++c) {
            int32_t x = k == 0 ? anywhere(rng) : baseX + (local(rng) >> (k * 3));
            int32_t y = k == 0 ? anywhere(rng) : baseY + (local(rng) >> (k * 3));
            if (k == 5 && c == 2) x = int32_t(batch.x[1][t]), y = int32_t(batch.y[1][t]);   // two corners equal
            batch.x[c][t] = x, batch.y[c][t] = y;
            batch.z[c][t] = unit(rng);
            batch.inverseW[c][t] = 0.25 + unit(rng);
            for (int v = 0; v < varyings; ++v) batch.varyings[v][c][t] = float(unit(rng) * 4.0 - 2.0);
        }
        const double depths[] = {0.0, 0x1p-1060, 0x1p-1000, unit(rng), 1.0};
        batch.maxDepth[t] = depths[t % 5];
        batch.primitiveId[t] = uint32_t(1000 + t);
    }
    batch.count = count;
    return batch;
}

std::vector<SetupConstants> constantCases() {
    std::vector<SetupConstants> cases;
    for (CullMode cull : {CullMode::None, CullMode::Back, CullMode::Front}) {
        for (bool conservative : {false, true}) {
            for (PolygonOffset offset : {PolygonOffset{0.0f, 0.0f}, PolygonOffset{1.1f, 4.0f}, PolygonOffset{0.0f, -2.0f}}) {
                for (int planeCount : {0, 4}) {
                    cases.push_back({kViewportWidth, kViewportHeight, 0, 0, kViewportWidth, kViewportHeight, cull,
                                     conservative, offset, planeCount});
                    // A window of the viewport (pipeline_state.h, ViewportWindow).
                    cases.push_back({kViewportWidth / 3, kViewportHeight / 2, 40, 24, kViewportWidth, kViewportHeight,
                                     cull, conservative, offset, planeCount});
                }
            }
        }
    }
    return cases;
}

bool sameBytes(const SetupOutput& a, const SetupOutput& b, int planeCount) {
    if (a.count != b.count) return false;
    for (int k = 0; k < a.count; ++k) {
        const TriangleSetup &s = a.triangles[k], &t = b.triangles[k];
        const bool same = std::memcmp(s.edgeA, t.edgeA, sizeof s.edgeA) == 0 && std::memcmp(s.edgeB, t.edgeB, sizeof s.edgeB) == 0 &&
                          std::memcmp(s.edgeC, t.edgeC, sizeof s.edgeC) == 0 && s.minX == t.minX && s.minY == t.minY &&
                          s.maxX == t.maxX && s.maxY == t.maxY && s.refX == t.refX && s.refY == t.refY && std::memcmp(&s.depth, &t.depth, sizeof s.depth) == 0 &&
                          s.primitiveId == t.primitiveId && s.frontFacing == t.frontFacing &&
                          std::memcmp(a.planes[k], b.planes[k], sizeof(Plane) * size_t(planeCount)) == 0;
        if (!same) return false;
    }
    return true;
}

int64_t floorDiv(int64_t a, int64_t b) { return a / b - ((a % b != 0) && ((a < 0) != (b < 0))); }
int64_t ceilDiv(int64_t a, int64_t b) { return -floorDiv(-a, b); }

// The oracle: setup of batch triangle t in int64 and in scalar double with frexp/ldexp, as
// the definitions in setup_triangles.inl read. Returns false when the triangle is culled.
bool oracleSetup(const SetupBatch& batch, int t, const SetupConstants& k, TriangleSetup& out, Plane* planes) {
    int64_t x[3], y[3];
    int first = 0;
    for (int c = 0; c < 3; ++c) x[c] = int64_t(batch.x[c][t]), y[c] = int64_t(batch.y[c][t]);
    for (int c = 1; c < 3; ++c) if (y[c] < y[first] || (y[c] == y[first] && x[c] < x[first])) first = c;
    int order[3] = {first, (first + 1) % 3, (first + 2) % 3};
    int64_t vx[3], vy[3];
    for (int c = 0; c < 3; ++c) vx[c] = x[order[c]], vy[c] = y[order[c]];
    const int64_t det = (vx[1] - vx[0]) * (vy[2] - vy[0]) - (vx[2] - vx[0]) * (vy[1] - vy[0]);
    if (det == 0) return false;
    out.frontFacing = det < 0;
    if ((k.cull == CullMode::Back && !out.frontFacing) || (k.cull == CullMode::Front && out.frontFacing)) return false;
    const int64_t lo[2] = {std::min({vx[0], vx[1], vx[2]}), std::min({vy[0], vy[1], vy[2]})};
    const int64_t hi[2] = {std::max({vx[0], vx[1], vx[2]}), std::max({vy[0], vy[1], vy[2]})};
    int64_t begin[2], end[2];
    for (int a = 0; a < 2; ++a) {
        begin[a] = k.conservative ? ceilDiv(lo[a] - 1, 256) - 1 : ceilDiv(lo[a] - 128, 256);
        end[a] = k.conservative ? floorDiv(hi[a] + 1, 256) + 1 : floorDiv(hi[a] - 128, 256) + 1;
    }
    // Bounds in the framebuffer (the window); the planes' reference pixel clamped to the viewport.
    out.minX = int32_t(std::max<int64_t>(begin[0] - k.windowX, 0)), out.minY = int32_t(std::max<int64_t>(begin[1] - k.windowY, 0));
    out.maxX = int32_t(std::min<int64_t>(end[0] - k.windowX, k.width)), out.maxY = int32_t(std::min<int64_t>(end[1] - k.windowY, k.height));
    const int64_t refX = std::max<int64_t>(begin[0], 0), refY = std::max<int64_t>(begin[1], 0);
    out.refX = int32_t(refX - k.windowX), out.refY = int32_t(refY - k.windowY);
    if (out.minX >= out.maxX || out.minY >= out.maxY) return false;
    const int64_t sign = det > 0 ? 1 : -1;
    for (int e = 0; e < 3; ++e) {
        const int a = e, b = (e + 1) % 3;
        const int64_t A = -sign * (vy[b] - vy[a]), B = sign * (vx[b] - vx[a]), C = -(A * vx[a] + B * vy[a]);
        const bool topLeft = A > 0 || (A == 0 && B > 0);
        const int64_t K = k.conservative ? 128 * (A + B) + C + 129 * (std::abs(A) + std::abs(B)) : 128 * (A + B) + C - (topLeft ? 0 : 1);
        out.edgeA[e] = int32_t(A), out.edgeB[e] = int32_t(B), out.edgeC[e] = floorDiv(K, 256) + A * k.windowX + B * k.windowY;
    }
    const double x0 = vx[0] / 256.0, y0 = vy[0] / 256.0;
    const double x1 = vx[1] / 256.0 - x0, y1 = vy[1] / 256.0 - y0, x2 = vx[2] / 256.0 - x0, y2 = vy[2] / 256.0 - y0;
    const double inverseDet = 1.0 / (x1 * y2 - x2 * y1);
    auto plane = [&](const double q[3], double offset, double* slopes) {
        const double perX = ((q[1] - q[0]) * y2 - (q[2] - q[0]) * y1) * inverseDet;
        const double perY = ((q[2] - q[0]) * x1 - (q[1] - q[0]) * x2) * inverseDet;
        if (slopes) slopes[0] = perX, slopes[1] = perY;
        return Plane{float(q[0] + perX * (double(refX) + 0.5 - x0) + perY * (double(refY) + 0.5 - y0) + offset), float(perX), float(perY)};
    };
    const double z[3] = {batch.z[order[0]][t], batch.z[order[1]][t], batch.z[order[2]][t]};
    double slopes[2];
    plane(z, 0.0, slopes);
    double offset = 0.0;
    if (k.offset.factor != 0.0f || k.offset.units != 0.0f) {
        int exponent = 0;
        std::frexp(batch.maxDepth[t], &exponent);
        const double maxSlope = std::max(std::abs(double(float(slopes[0]))), std::abs(double(float(slopes[1]))));
        offset = k.offset.factor * maxSlope + k.offset.units * std::ldexp(1.0, exponent - 24);
    }
    out.depth = plane(z, offset, nullptr);
    if (k.planeCount > 0) {
        const double w[3] = {batch.inverseW[order[0]][t], batch.inverseW[order[1]][t], batch.inverseW[order[2]][t]};
        planes[0] = plane(w, 0.0, nullptr);
        for (int v = 0; v + 1 < k.planeCount; ++v) {
            const double q[3] = {batch.varyings[v][order[0]][t] * w[0], batch.varyings[v][order[1]][t] * w[1],
                                 batch.varyings[v][order[2]][t] * w[2]};
            planes[1 + v] = plane(q, 0.0, nullptr);
        }
    }
    out.primitiveId = batch.primitiveId[t];
    out.varyings = nullptr;
    return true;
}

}  // namespace

TEST_CASE("setup kernels: every SIMD level gives the scalar build's bytes, for every state and short batches") {
    std::mt19937 rng(7);
    const SetupKernel scalar = rasterKernels(SimdLevel::Scalar).setup;
    int compared = 0;
    for (const SetupConstants& k : constantCases()) {
        for (int count : {1, 5, 13, kSetupBatchSize}) {
            const SetupBatch batch = randomBatch(rng, count, 3);
            SetupOutput expected;
            scalar(batch, k, expected);
            for (SimdLevel level : test::supportedLevels()) {
                SetupOutput got;
                rasterKernels(level).setup(batch, k, got);
                CHECK_MESSAGE(sameBytes(got, expected, k.planeCount), simdLevelName(level));
                compared += got.count;
            }
        }
    }
    CHECK(compared > 500);   // enough triangles survive culling to mean something
}

TEST_CASE("setup kernel: edges, bounds and planes equal the int64 and frexp/ldexp definitions") {
    std::mt19937 rng(11);
    int accepted = 0, culledByCount = 0;
    for (const SetupConstants& k : constantCases()) {
        for (int round = 0; round < 8; ++round) {
            const SetupBatch batch = randomBatch(rng, kSetupBatchSize, 3);
            SetupOutput expected{};
            for (int t = 0; t < batch.count; ++t) {
                if (oracleSetup(batch, t, k, expected.triangles[expected.count], expected.planes[expected.count])) ++expected.count;
            }
            for (SimdLevel level : test::supportedLevels()) {
                SetupOutput got;
                rasterKernels(level).setup(batch, k, got);
                REQUIRE_MESSAGE(sameBytes(got, expected, k.planeCount), simdLevelName(level));
            }
            accepted += expected.count;
            culledByCount += batch.count - expected.count;
        }
    }
    CHECK(accepted > 1000);
    CHECK(culledByCount > 100);
}

TEST_CASE("snapping: roundToEven is nearbyint's rounding over the whole snapped range, ties and signs included") {
    // Every tie in the range rounds to the even neighbour, as nearbyint does; a broken shift
    // (2^52 alone, or truncation) would round half of them the other way.
    for (double x : {0.5, 1.5, 2.5, -0.5, -1.5, -2.5, 0x1p22 - 0.5, -0x1p22 + 0.5, 0.49999999999999994, -0.0}) {
        CAPTURE(x);
        CHECK(int32_t(roundToEven(x)) == int32_t(std::nearbyint(x)));
    }
    std::mt19937_64 random(37);
    std::uniform_real_distribution<double> coordinate(-0x1p23, 0x1p23);
    for (int k = 0; k < 100000; ++k) {
        const double x = coordinate(random), tie = std::floor(x) + 0.5;
        CAPTURE(x);
        CHECK(roundToEven(x) == std::nearbyint(x));
        CHECK(roundToEven(tie) == std::nearbyint(tie));
    }
}
