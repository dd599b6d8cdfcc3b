// The irregular z-buffer's vector kernels (shadows/izb/kernels.h): the AVX2 and AVX-512
// builds against their scalar twin, bit for bit, and the scalar twin against the plain
// double expressions it replaces (the reference's ray set-up, segmentBlocked on each
// receiver); and the whole technique giving the same bytes at every SIMD level.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <array>
#include <random>
#include <string>
#include <vector>

#include "frame/registry.h"
#include "frame/render.h"
#include "scenes/scene_file.h"
#include "shadows/izb/izb.h"
#include "shadows/ray_offset.h"
#include "tests/raster/raster_test_util.h"
#include "tests/same_bits.h"

using namespace shadowlab;

using test::supportedLevels;

namespace {

// Points on a 10 m scene, some far outside it (so max |P_k| sets the offset), unit normals;
// a few within a hair of the point light (no segment left).
struct PointSet {
    std::vector<double> column[6];
    explicit PointSet(size_t n, const glm::dvec3& light, std::mt19937& rng) {
        std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
        for (std::vector<double>& c : column) c.assign(n + izb::kKernelPadding, 0.0);
        for (size_t k = 0; k < n; ++k) {
            const float reach = k % 7 == 0 ? 300.0f : 5.0f;
            glm::vec3 P(reach * unit(rng), reach * unit(rng), reach * unit(rng));
            if (k % 101 == 0) P = glm::vec3(light) + 1e-6f * glm::vec3(unit(rng), unit(rng), unit(rng));
            const glm::vec3 N = glm::normalize(glm::vec3(unit(rng), unit(rng), unit(rng)) + glm::vec3(0.0f, 0.01f, 0.0f));
            column[0][k] = P.x, column[1][k] = P.y, column[2][k] = P.z;
            column[3][k] = N.x, column[4][k] = N.y, column[5][k] = N.z;
        }
    }
    izb::PointColumns points() const {
        return {column[0].data(), column[1].data(), column[2].data(), column[3].data(), column[4].data(), column[5].data()};
    }
};

struct SegmentSet {
    std::vector<double> column[4];
    explicit SegmentSet(size_t n) {
        for (std::vector<double>& c : column) c.assign(n + izb::kKernelPadding, -1.0);
    }
    izb::SegmentColumns segments() { return {column[0].data(), column[1].data(), column[2].data(), column[3].data()}; }
};

}  // namespace

TEST_CASE("izb segments kernel: every SIMD level gives the scalar twin's bits, which are the reference's ray set-up") {
    std::mt19937 rng(3);
    const double diagonal = 10.0;
    const size_t n = 1000 + 3;   // a tail shorter than any vector
    for (const glm::dvec4 light : {glm::dvec4(1.5, 6.0, -2.0, 1.0), glm::dvec4(glm::normalize(glm::dvec3(0.3, 1.0, 0.2)), 0.0)}) {
        CAPTURE(light.w);
        const PointSet points(n, glm::dvec3(light), rng);
        const izb::SegmentConstants constants{{light.x, light.y, light.z, light.w}, diagonal, kShadowRayOffsetPerScale};
        SegmentSet scalar(n);
        izb::kernelsScalar().segments(constants, points.points(), uint32_t(n), scalar.segments());
        size_t noSegment = 0;
        for (size_t k = 0; k < n; ++k) {
            const glm::vec3 P(float(points.column[0][k]), float(points.column[1][k]), float(points.column[2][k]));
            const glm::dvec3 N(points.column[3][k], points.column[4][k], points.column[5][k]);
            const double offset = shadowRayOffset(P, diagonal);
            const glm::vec3 origin(glm::dvec3(P) + offset * N);
            const double tFar = light.w == 0.0 ? INFINITY : 1.0 - offset / glm::length(glm::dvec3(light) - glm::dvec3(origin));
            CHECK(scalar.column[0][k] == double(origin.x));
            CHECK(scalar.column[1][k] == double(origin.y));
            CHECK(scalar.column[2][k] == double(origin.z));
            CHECK(scalar.column[3][k] == tFar);
            noSegment += tFar <= 0.0;
        }
        if (light.w != 0.0) CHECK(noSegment > 0);
        for (raster::SimdLevel level : supportedLevels()) {
            CAPTURE(raster::simdLevelName(level));
            SegmentSet vector(n);
            izb::kernels(level).segments(constants, points.points(), uint32_t(n), vector.segments());
            for (int c = 0; c < 4; ++c) {
                CHECK(std::memcmp(vector.column[c].data(), scalar.column[c].data(), n * sizeof(double)) == 0);
            }
        }
    }
}

TEST_CASE("izb occlusion kernel: every SIMD level sets exactly the bytes segmentBlocked() finds, inside the run only") {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const size_t n = 515;
    // Receivers on the plane y = 0 below a triangle fan at y = 1, a third of them exactly
    // below a shared edge or a vertex (where only watertightness keeps the segment blocked).
    const glm::dvec3 fan[4] = {{-1.0, 1.0, -1.0}, {1.0, 1.0, -1.0}, {1.0, 1.0, 1.0}, {-1.0, 1.0, 1.0}};
    std::vector<float> x(n + izb::kKernelPadding, 0.0f), y = x, z = x;
    std::vector<double> tFar(n + izb::kKernelPadding, 0.0);
    for (size_t k = 0; k < n; ++k) {
        x[k] = float(1.5 * unit(rng)), z[k] = float(1.5 * unit(rng));
        if (k % 3 == 0) z[k] = x[k];   // under the diagonal shared by the fan's two triangles
    }
    const izb::ReceiverColumns receivers{x.data(), y.data(), z.data(), tFar.data()};
    for (const glm::dvec4 light : {glm::dvec4(0.1, 4.0, 0.2, 1.0), glm::dvec4(glm::normalize(glm::dvec3(0.2, 1.0, -0.1)), 0.0)}) {
        // Segments reach the light (tFar 1, or unbounded towards a directional one), but
        // some stop short of the occluder.
        for (size_t k = 0; k < n; ++k) tFar[k] = k % 11 == 0 ? 0.1 : light.w == 0.0 ? INFINITY : 1.0;
        std::vector<uint8_t> underFan(n, 0);   // blocked by either triangle
        for (const auto& corners : {std::array<int, 3>{0, 1, 2}, std::array<int, 3>{0, 2, 3}}) {
            izb::OccluderTriangle occluder{{}, {light.x, light.y, light.z, light.w}};
            glm::dvec3 triangle[3];
            for (int v = 0; v < 3; ++v) {
                triangle[v] = fan[corners[v]];
                for (int c = 0; c < 3; ++c) occluder.vertex[3 * v + c] = triangle[v][c];
            }
            std::vector<uint8_t> expected(n, 0);
            size_t blocked = 0;
            for (size_t k = 0; k < n; ++k) {
                const glm::dvec3 o(x[k], y[k], z[k]);
                expected[k] = izb::segmentBlocked(o, glm::dvec3(light) - light.w * o, tFar[k], triangle);
                blocked += expected[k];
                underFan[k] |= expected[k];
            }
            CHECK(blocked > n / 10);
            for (raster::SimdLevel level : supportedLevels()) {
                CAPTURE(raster::simdLevelName(level));
                for (const auto& range : {std::pair<uint32_t, uint32_t>{0, uint32_t(n)}, {3, 4}, {5, 18}, {100, 100}, {7, uint32_t(n - 2)}}) {
                    const uint32_t begin = range.first, end = range.second;
                    CAPTURE(begin);
                    CAPTURE(end);
                    std::vector<uint8_t> got(n, 2);   // 2: untouched
                    izb::kernels(level).occlusion(occluder, receivers, begin, end, got.data());
                    size_t wrong = 0;
                    for (size_t k = 0; k < n; ++k) {
                        const bool inside = k >= begin && k < end;
                        wrong += got[k] != (inside && expected[k] ? 1 : 2);
                    }
                    CHECK(wrong == 0);
                }
            }
        }
        // Watertight: every full segment whose line meets the fan's square strictly inside
        // is blocked by one of its triangles, those under the shared diagonal included.
        size_t leaks = 0;
        for (size_t k = 0; k < n; ++k) {
            const glm::dvec3 o(x[k], y[k], z[k]);
            const glm::dvec3 d = glm::dvec3(light) - light.w * o;
            const glm::dvec3 atFan = o + d * (1.0 / d.y);
            leaks += tFar[k] > 0.1 && std::abs(atFan.x) < 0.999 && std::abs(atFan.z) < 0.999 && !underFan[k];
        }
        CHECK(leaks == 0);
    }
}

TEST_CASE("izb crossing kernel: every SIMD level lists the scalar twin's hits bit for bit, which are segmentBlocked's "
          "with the plain barycentric coordinates") {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const size_t n = 517;
    // Receivers on y = 0 under a tilted triangle, some under its edges and corners.
    const glm::dvec3 triangle[3] = {{-1.0, 1.0, -0.8}, {1.2, 1.3, -1.0}, {0.1, 0.8, 1.1}};
    std::vector<float> x(n + izb::kKernelPadding, 0.0f), y = x, z = x;
    std::vector<double> tFar(n + izb::kKernelPadding, 0.0);
    for (size_t k = 0; k < n; ++k) x[k] = float(1.5 * unit(rng)), z[k] = float(1.5 * unit(rng));
    const izb::ReceiverColumns receivers{x.data(), y.data(), z.data(), tFar.data()};
    for (const glm::dvec4 light : {glm::dvec4(0.1, 4.0, 0.2, 1.0), glm::dvec4(glm::normalize(glm::dvec3(0.2, 1.0, -0.1)), 0.0)}) {
        for (size_t k = 0; k < n; ++k) tFar[k] = k % 13 == 0 ? 0.1 : light.w == 0.0 ? INFINITY : 1.0;
        izb::OccluderTriangle occluder{{}, {light.x, light.y, light.z, light.w}};
        for (int v = 0; v < 3; ++v) {
            for (int c = 0; c < 3; ++c) occluder.vertex[3 * v + c] = triangle[v][c];
        }
        // The scalar twin against the plain expressions: the hits are segmentBlocked's, and
        // (u, v) the signed volumes det(C, A, d) and det(A, B, d) over their sum with det(B, C, d).
        std::vector<izb::SegmentHit> scalar(n);
        const uint32_t count = izb::kernelsScalar().crossings(occluder, receivers, 0, uint32_t(n), scalar.data());
        scalar.resize(count);
        std::vector<izb::SegmentHit> expected;
        for (size_t k = 0; k < n; ++k) {
            const glm::dvec3 o(x[k], y[k], z[k]), d = glm::dvec3(light) - light.w * o;
            if (!izb::segmentBlocked(o, d, tFar[k], triangle)) continue;
            const glm::dvec3 A = triangle[0] - o, B = triangle[1] - o, C = triangle[2] - o;
            const double eAB = glm::dot(glm::cross(A, B), d), eBC = glm::dot(glm::cross(B, C), d);
            const double eCA = glm::dot(glm::cross(C, A), d), nd = eAB + eBC + eCA;
            expected.push_back({uint32_t(k), float(eCA / nd), float(eAB / nd)});
        }
        REQUIRE(expected.size() > n / 10);
        REQUIRE(count == expected.size());
        size_t wrong = 0;
        for (size_t h = 0; h < count; ++h) {
            wrong += scalar[h].receiver != expected[h].receiver || scalar[h].u != expected[h].u || scalar[h].v != expected[h].v;
        }
        CHECK(wrong == 0);
        for (raster::SimdLevel level : supportedLevels()) {
            CAPTURE(raster::simdLevelName(level));
            for (const auto& range : {std::pair<uint32_t, uint32_t>{0, uint32_t(n)}, {3, 4}, {5, 18}, {100, 100}, {7, uint32_t(n - 2)}}) {
                CAPTURE(range.first);
                CAPTURE(range.second);
                std::vector<izb::SegmentHit> got(n + 1, izb::SegmentHit{~0u, -1.0f, -1.0f});
                const uint32_t gotCount = izb::kernels(level).crossings(occluder, receivers, range.first, range.second, got.data());
                std::vector<izb::SegmentHit> want;
                for (const izb::SegmentHit& h : scalar) {
                    if (h.receiver >= range.first && h.receiver < range.second) want.push_back(h);
                }
                REQUIRE(gotCount == want.size());
                CHECK(test::sameBytes(std::vector<izb::SegmentHit>(got.begin(), got.begin() + gotCount), want));
                CHECK(got[gotCount].receiver == ~0u);   // nothing written past the count
            }
        }
    }
}

namespace {

// izb's V at every supported SIMD level against the scalar build's, bytewise.
void checkSameBytesAtEveryLevel(Scene scene) {
    PreparedScene prepared(std::move(scene));
    const GBuffer g = renderGBuffer(prepared.world(), prepared.scene().camera, raster::SimdLevel::Scalar);
    const Technique& t = findTechnique("izb");
    const TechniqueParams params(t.name, t.params, {});
    const auto visibility = [&](raster::SimdLevel level) {
        return t.run({.prepared = prepared,
                      .gbuffer = g,
                      .light = prepared.scene().lights[0],
                      .simd = level,
                      .params = params}).visibility;
    };
    const std::vector<float> scalar = visibility(raster::SimdLevel::Scalar);
    for (raster::SimdLevel level : supportedLevels()) {
        CAPTURE(raster::simdLevelName(level));
        const std::vector<float> other = visibility(level);
        CHECK(test::sameBytes(other, scalar));
    }
}

}  // namespace

TEST_CASE("izb gives the same bytes at every SIMD level") {
    checkSameBytesAtEveryLevel(loadScene("sphere-box"));
}

TEST_CASE("izb gives the same bytes at every SIMD level on cut-outs") {
    Scene foliage = loadScene(std::string(SHADOWLAB_SOURCE_DIR) + "/assets/scenes/volumetric/foliage-cards.json");
    foliage.camera.width = 320, foliage.camera.height = 200;
    checkSameBytesAtEveryLevel(std::move(foliage));
}
