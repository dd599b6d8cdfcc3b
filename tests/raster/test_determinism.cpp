// Determinism: the same draws give the same bytes for 1, 2 and 8 threads and for the
// scalar, AVX2 and AVX-512 kernels (the scalar kernel is the reference twin).
#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <random>
#include <sstream>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "raster/rasterizer.h"
#include "raster/thread_count.h"
#include "tests/same_bits.h"

using namespace shadowlab::raster;
using shadowlab::test::sameBytes;

namespace {

// Many overlapping spheres of random sizes and a large ground quad: small and large
// triangles, both facings, clipping at the near plane, and depth ties.
struct TestScene {
    std::vector<glm::vec3> positions;
    std::vector<float> varyings;   // RGBA per vertex
    std::vector<glm::uvec3> triangles;

    TestScene() {
        std::mt19937 rng(5);
        std::uniform_real_distribution<float> u(-1.0f, 1.0f);
        addQuad();
        for (int s = 0; s < 60; ++s) addSphere(glm::vec3(4 * u(rng), 1 + u(rng), 4 * u(rng) - 2), 0.2f + 0.4f * (u(rng) + 1), 8 + s % 24);
    }
    void addVertex(const glm::vec3& p) {
        positions.push_back(p);
        varyings.insert(varyings.end(), {p.x, p.y, p.z, 1.0f});
    }
    void addQuad() {
        const auto base = uint32_t(positions.size());
        for (glm::vec3 p : {glm::vec3(-30, 0, 30), glm::vec3(30, 0, 30), glm::vec3(30, 0, -30), glm::vec3(-30, 0, -30)}) addVertex(p);
        triangles.push_back({base, base + 1, base + 2});
        triangles.push_back({base, base + 2, base + 3});
    }
    void addSphere(const glm::vec3& c, float r, int n) {
        const auto base = uint32_t(positions.size());
        for (int s = 0; s <= n; ++s) {
            for (int k = 0; k < 2 * n; ++k) {
                const float theta = float(M_PI) * s / n, phi = float(M_PI) * k / n;
                addVertex(c + r * glm::vec3(std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi)));
            }
        }
        auto at = [&](int s, int k) { return base + uint32_t(s * 2 * n + k % (2 * n)); };
        for (int s = 0; s < n; ++s) {
            for (int k = 0; k < 2 * n; ++k) {
                triangles.push_back({at(s, k), at(s + 1, k), at(s, k + 1)});
                triangles.push_back({at(s, k + 1), at(s + 1, k), at(s + 1, k + 1)});
            }
        }
    }
};

struct Outputs {
    std::vector<float> depth, red, alpha;
    std::vector<uint8_t> stencil;
    std::vector<uint32_t> ids;
};

Outputs render(SimdLevel level, const TestScene& scene) {
    Framebuffer fb(333, 257, {.stencil = true, .color = true, .primitiveId = true});
    Rasterizer r(level);
    DrawCall call;
    call.vertices.positions = scene.positions;
    call.vertices.varyings = scene.varyings;
    call.vertices.varyingCount = 4;
    call.triangles = scene.triangles;
    call.clipFromObject = glm::perspective(0.9f, 333.0f / 257.0f, 0.3f, 30.0f) *
                          glm::lookAt(glm::vec3(0.5f, 2.5f, 4.0f), glm::vec3(0, 0.5f, -2), glm::vec3(0, 1, 0));
    PipelineState s;
    s.output = FragmentOutput::PrimitiveId;
    r.draw(fb, s, call);
    s.output = FragmentOutput::VaryingColor;
    s.depth.func = CompareFunc::LessEqual;
    s.blend = {true, BlendEquation::Add, BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha};
    s.offset = {1.0f, 2.0f};
    r.draw(fb, s, call);
    s.cull = CullMode::None;
    s.depth.write = false;
    s.stencil.enabled = true;
    s.stencil.front.depthFail = StencilOp::IncrementWrap;
    s.stencil.back.depthFail = StencilOp::DecrementWrap;
    s.output = FragmentOutput::DepthOnly;
    r.draw(fb, s, call);
    return {fb.depthImage(), fb.colorImage(0), fb.colorImage(3), fb.stencilImage(), fb.primitiveIdImage()};
}

}  // namespace

TEST_CASE("scalar, AVX2 and AVX-512 kernels at 1, 2 and 8 threads give identical bytes") {
    const TestScene scene;
    const Outputs reference = shadowlab::withThreads(1, [&] { return render(SimdLevel::Scalar, scene); });
    int covered = 0;
    for (uint32_t id : reference.ids) covered += id != 0;
    CHECK(covered > 333 * 257 / 3);
    for (SimdLevel level : {SimdLevel::Scalar, SimdLevel::Avx2, SimdLevel::Avx512}) {
        if (!simdLevelSupported(level)) {
            MESSAGE("skipped: this CPU has no " << simdLevelName(level));
            continue;
        }
        for (int threads : {1, 2, 8}) {
            const Outputs o = shadowlab::withThreads(threads, [&] { return render(level, scene); });
            INFO(simdLevelName(level) << " with " << threads << " threads");
            CHECK(sameBytes(o.depth, reference.depth));
            CHECK(sameBytes(o.red, reference.red));
            CHECK(sameBytes(o.alpha, reference.alpha));
            CHECK(sameBytes(o.stencil, reference.stencil));
            CHECK(sameBytes(o.ids, reference.ids));
        }
    }
}

// Tests pass over a SIMD level this CPU lacks. So that a broken detection cannot turn every
// vector test into a silent skip, .ci/run lists the levels /proc/cpuinfo shows in
// SHADOWLAB_REQUIRE_SIMD, and each must be detected (and so tested).
TEST_CASE("every SIMD level the CI machine has is detected, so none of its tests is skipped") {
    const char* required = std::getenv("SHADOWLAB_REQUIRE_SIMD");
    if (!required || !*required) {
        MESSAGE("SHADOWLAB_REQUIRE_SIMD is not set (.ci/run sets it): nothing required");
        return;
    }
    std::stringstream names(required);
    int checked = 0;
    for (std::string name; std::getline(names, name, ',');) {
        INFO("SHADOWLAB_REQUIRE_SIMD names " << name);
        CHECK(simdLevelSupported(parseSimdLevel(name)));
        ++checked;
    }
    CHECK(checked > 0);
}
