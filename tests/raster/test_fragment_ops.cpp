// Depth, stencil, polygon offset, blending and colour mask, each against its OpenGL
// definition written out here independently of the kernels.
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>

#include "tests/raster/raster_test_util.h"

using namespace shadowlab;
using namespace shadowlab::raster;
using shadowlab::test::supportedLevels;

namespace {

constexpr int kSize = 16;

// Two triangles covering the whole 16x16 framebuffer at depth z; `clockwise` flips the
// winding so the quad is back-facing.
struct FullQuad {
    std::vector<glm::vec3> p;
    std::vector<glm::uvec3> t;
    FullQuad(float z, bool backFacing = false) {
        p = {{0, 0, z}, {kSize, 0, z}, {kSize, kSize, z}, {0, kSize, z}};
        // Window y grows downwards, so (0,0) -> (0,16) -> (16,16) is counter-clockwise in NDC.
        t = backFacing ? std::vector<glm::uvec3>{{0, 1, 2}, {0, 2, 3}} : std::vector<glm::uvec3>{{0, 3, 2}, {0, 2, 1}};
    }
};

bool compareDefinition(CompareFunc f, float a, float b) {
    switch (f) {
        case CompareFunc::Never: return false;
        case CompareFunc::Less: return a < b;
        case CompareFunc::Equal: return a == b;
        case CompareFunc::LessEqual: return a <= b;
        case CompareFunc::Greater: return a > b;
        case CompareFunc::NotEqual: return a != b;
        case CompareFunc::GreaterEqual: return a >= b;
        case CompareFunc::Always: return true;
    }
    return false;
}

uint8_t stencilOpDefinition(StencilOp op, uint8_t s, uint8_t ref) {
    switch (op) {
        case StencilOp::Keep: return s;
        case StencilOp::Zero: return 0;
        case StencilOp::Replace: return ref;
        case StencilOp::Increment: return s == 255 ? 255 : uint8_t(s + 1);
        case StencilOp::Decrement: return s == 0 ? 0 : uint8_t(s - 1);
        case StencilOp::IncrementWrap: return uint8_t(s + 1);
        case StencilOp::DecrementWrap: return uint8_t(s - 1);
        case StencilOp::Invert: return uint8_t(~s);
    }
    return s;
}

constexpr CompareFunc kAllFuncs[] = {CompareFunc::Never, CompareFunc::Less, CompareFunc::Equal, CompareFunc::LessEqual,
                                     CompareFunc::Greater, CompareFunc::NotEqual, CompareFunc::GreaterEqual, CompareFunc::Always};
constexpr StencilOp kAllOps[] = {StencilOp::Keep, StencilOp::Zero, StencilOp::Replace, StencilOp::Increment,
                                 StencilOp::Decrement, StencilOp::IncrementWrap, StencilOp::DecrementWrap, StencilOp::Invert};

}  // namespace

TEST_CASE("depth test: every compare function and the write mask") {
    for (SimdLevel level : supportedLevels()) {
        Rasterizer r(level);
        for (CompareFunc func : kAllFuncs) {
            for (float z : {0.25f, 0.5f, 0.75f}) {
                for (bool write : {false, true}) {
                    Framebuffer fb(kSize, kSize, {.stencil = true});
                    fb.clearDepth(0.5f);
                    PipelineState s;
                    s.depth = {true, write, func};
                    s.stencil.enabled = true;   // records which fragments passed
                    s.stencil.front.depthPass = StencilOp::Replace;
                    s.stencil.front.reference = 1;
                    FullQuad q(z);
                    r.draw(fb, s, test::windowDraw(fb, q.p, q.t));
                    const bool pass = compareDefinition(func, z, 0.5f);
                    const auto depth = fb.depthImage();
                    const auto stencil = fb.stencilImage();
                    INFO("func " << int(func) << " z " << z << " write " << write);
                    for (size_t i = 0; i < depth.size(); ++i) {
                        REQUIRE(stencil[i] == (pass ? 1 : 0));
                        REQUIRE(depth[i] == (pass && write ? z : 0.5f));
                    }
                }
            }
        }
    }
}

TEST_CASE("stencil: every operation on every outcome, with reference and write mask") {
    const uint8_t reference = 0x5a, writeMask = 0xf3;
    for (SimdLevel level : supportedLevels()) {
        Rasterizer r(level);
        for (StencilOp op : kAllOps) {
            for (uint8_t initial : {uint8_t(0), uint8_t(1), uint8_t(0x80), uint8_t(0xff)}) {
                // outcome 0: stencil fails; 1: stencil passes, depth fails; 2: both pass.
                for (int outcome = 0; outcome < 3; ++outcome) {
                    Framebuffer fb(kSize, kSize, {.stencil = true});
                    fb.clearStencil(initial);
                    fb.clearDepth(0.5f);
                    PipelineState s;
                    s.stencil.enabled = true;
                    StencilFace& f = s.stencil.front;
                    f.func = outcome == 0 ? CompareFunc::Never : CompareFunc::Always;
                    f.reference = reference;
                    f.writeMask = writeMask;
                    (outcome == 0 ? f.stencilFail : outcome == 1 ? f.depthFail : f.depthPass) = op;
                    FullQuad q(outcome == 1 ? 0.75f : 0.25f);
                    r.draw(fb, s, test::windowDraw(fb, q.p, q.t));
                    const uint8_t next = stencilOpDefinition(op, initial, reference);
                    const uint8_t expected = uint8_t((initial & ~writeMask) | (next & writeMask));
                    const auto stencil = fb.stencilImage();
                    INFO("op " << int(op) << " initial " << int(initial) << " outcome " << outcome);
                    for (uint8_t v : stencil) REQUIRE(v == expected);
                }
            }
        }
    }
}

TEST_CASE("stencil compare: (reference & mask) FUNC (stored & mask)") {
    for (CompareFunc func : kAllFuncs) {
        for (int stored : {0x10, 0x37, 0x3f, 0xf7}) {
            Framebuffer fb(kSize, kSize, {.stencil = true});
            fb.clearStencil(uint8_t(stored));
            PipelineState s;
            s.stencil.enabled = true;
            s.stencil.front = {func, StencilOp::Zero, StencilOp::Keep, StencilOp::Replace, 0x37, 0x3c, 0xff};
            FullQuad q(0.5f);
            Rasterizer r;
            r.draw(fb, s, test::windowDraw(fb, q.p, q.t));
            const bool pass = compareDefinition(func, float(0x37 & 0x3c), float(stored & 0x3c));
            INFO("func " << int(func) << " stored " << stored);
            CHECK(fb.stencilImage()[0] == (pass ? 0x37 : 0));
        }
    }
}

TEST_CASE("two-sided stencil applies the front or back operations by facing") {
    Framebuffer fb(kSize, kSize, {.stencil = true});
    fb.clearStencil(10);
    PipelineState s;
    s.cull = CullMode::None;
    s.depth.test = false;
    s.stencil.enabled = true;
    s.stencil.front.depthPass = StencilOp::IncrementWrap;
    s.stencil.back.depthPass = StencilOp::DecrementWrap;
    Rasterizer r;
    FullQuad front(0.5f), back(0.5f, true);
    r.draw(fb, s, test::windowDraw(fb, front.p, front.t));
    r.draw(fb, s, test::windowDraw(fb, front.p, front.t));
    r.draw(fb, s, test::windowDraw(fb, back.p, back.t));
    for (uint8_t v : fb.stencilImage()) REQUIRE(v == 11);
}

TEST_CASE("back and front culling follow the counter-clockwise front-face convention") {
    FullQuad front(0.5f), back(0.5f, true);
    for (CullMode cull : {CullMode::None, CullMode::Back, CullMode::Front}) {
        Framebuffer fb(kSize, kSize, {.stencil = true});
        PipelineState s = test::countingState();
        s.cull = cull;
        Rasterizer r;
        r.draw(fb, s, test::windowDraw(fb, front.p, front.t));
        r.draw(fb, s, test::windowDraw(fb, back.p, back.t));
        const int expected = cull == CullMode::None ? 2 : 1;
        for (uint8_t v : fb.stencilImage()) REQUIRE(v == expected);
    }
}

TEST_CASE("polygon offset adds factor * max slope + units * r, as OpenGL defines it") {
    // z = 0.3 + 0.001 x + 0.002 y at pixel centres: max slope 0.002 per pixel.
    auto z = [](double x, double y) { return 0.3 + 0.001 * x + 0.002 * y; };
    const std::vector<glm::vec3> p = {{0, 0, float(z(0, 0))}, {0, kSize, float(z(0, kSize))}, {kSize, 0, float(z(kSize, 0))}};
    Framebuffer plain(kSize, kSize), offset(kSize, kSize);
    PipelineState s;
    s.cull = CullMode::None;
    Rasterizer r;
    r.draw(plain, s, test::windowDraw(plain, p, {{0, 1, 2}}));
    s.offset = {2.0f, 3.0f};
    r.draw(offset, s, test::windowDraw(offset, p, {{0, 1, 2}}));
    // The largest depth is z(0, 16) = 0.332 in [0.25, 0.5): exponent -2, r = 2^(-2 - 23).
    const double expectedOffset = 2.0 * 0.002 + 3.0 * std::ldexp(1.0, -25);
    const auto a = plain.depthImage(), b = offset.depthImage();
    int checked = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        if (a[i] == 1.0f) continue;
        CHECK(double(b[i]) - double(a[i]) == doctest::Approx(expectedOffset).epsilon(1e-3));
        CHECK(double(a[i]) == doctest::Approx(z(double(i % kSize) + 0.5, double(i / kSize) + 0.5)).epsilon(1e-6));
        ++checked;
    }
    CHECK(checked > 100);
}

TEST_CASE("blending: every equation, with factors, and the colour write mask") {
    const glm::vec4 dst(0.25f, 0.5f, 0.75f, 0.5f), src(0.5f, 0.25f, 1.0f, 0.25f);
    struct Case {
        BlendEquation eq;
        BlendFactor sf, df;
    };
    const Case cases[] = {{BlendEquation::Add, BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha},
                          {BlendEquation::Add, BlendFactor::One, BlendFactor::One},
                          {BlendEquation::Subtract, BlendFactor::One, BlendFactor::DstColor},
                          {BlendEquation::ReverseSubtract, BlendFactor::SrcColor, BlendFactor::OneMinusDstAlpha},
                          {BlendEquation::Min, BlendFactor::Zero, BlendFactor::Zero},
                          {BlendEquation::Max, BlendFactor::Zero, BlendFactor::Zero}};
    for (SimdLevel level : supportedLevels()) {
        for (const Case& c : cases) {
            Framebuffer fb(kSize, kSize, {.color = true});
            fb.clearColor(dst);
            PipelineState s;
            s.depth.test = false;
            s.output = FragmentOutput::ConstantColor;
            s.blend = {true, c.eq, c.sf, c.df};
            s.colorWriteMask = 0xb;   // R, G and A; B stays
            FullQuad q(0.5f);
            DrawCall call = test::windowDraw(fb, q.p, q.t);
            call.constantColor = src;
            Rasterizer r(level);
            r.draw(fb, s, call);
            for (int ch = 0; ch < 4; ++ch) {
                auto factor = [&](BlendFactor f) {
                    switch (f) {
                        case BlendFactor::Zero: return 0.0f;
                        case BlendFactor::One: return 1.0f;
                        case BlendFactor::SrcColor: return src[ch];
                        case BlendFactor::DstColor: return dst[ch];
                        case BlendFactor::SrcAlpha: return src.a;
                        case BlendFactor::OneMinusSrcAlpha: return 1.0f - src.a;
                        case BlendFactor::OneMinusDstAlpha: return 1.0f - dst.a;
                        default: return -1.0f;
                    }
                };
                const float s1 = src[ch] * factor(c.sf), d1 = dst[ch] * factor(c.df);
                float expected = c.eq == BlendEquation::Add ? s1 + d1
                               : c.eq == BlendEquation::Subtract ? s1 - d1
                               : c.eq == BlendEquation::ReverseSubtract ? d1 - s1
                               : c.eq == BlendEquation::Min ? std::min(src[ch], dst[ch]) : std::max(src[ch], dst[ch]);
                if (ch == 2) expected = dst[ch];
                INFO("equation " << int(c.eq) << " channel " << ch);
                for (float v : fb.colorImage(ch)) REQUIRE(v == expected);
            }
        }
    }
}

TEST_CASE("the build does not contract a*b+c into a fused multiply-add") {
    // Determinism contract: with -ffp-contract=off the product is rounded before the sum.
    volatile float a = 1.0f + std::ldexp(1.0f, -12), b = a, c = -1.0f;
    const float separate = a * b + c;
    CHECK(separate != std::fma(float(a), float(b), float(c)));
    CHECK(separate == std::ldexp(1.0f, -11));
}

TEST_CASE("draw rejects bad input with a clear error") {
    Framebuffer fb(kSize, kSize);
    Rasterizer r;
    const std::vector<glm::vec3> p = {{0, 0, 0.5f}, {1, 0, 0.5f}, {0, 1, 0.5f}};
    PipelineState s;
    CHECK_THROWS_AS(r.draw(fb, s, test::windowDraw(fb, p, {{0, 1, 3}})), std::invalid_argument);
    s.stencil.enabled = true;
    CHECK_THROWS_AS(r.draw(fb, s, test::windowDraw(fb, p, {{0, 1, 2}})), std::invalid_argument);
    s = {};
    s.output = FragmentOutput::PrimitiveId;
    CHECK_THROWS_AS(r.draw(fb, s, test::windowDraw(fb, p, {{0, 1, 2}})), std::invalid_argument);
    CHECK_THROWS_AS(Framebuffer(0, 10), std::invalid_argument);
    CHECK_THROWS_AS(Framebuffer(kMaxViewport + 1, 10), std::invalid_argument);
    CHECK_THROWS_AS(parseSimdLevel("sse9"), std::invalid_argument);
}

TEST_CASE("lazy clears: untouched tiles read as the clear value, a second clear undoes a draw, takeDepth is resolved") {
    // 200 x 130 pixels: 4 x 3 tiles, the last column and row partial. One small quad in
    // tile (1, 0) only; every other tile is never written by the draw.
    constexpr int kWidth = 200, kHeight = 130;
    const std::vector<glm::vec3> p = {{70, 10, 0.25f}, {90, 10, 0.25f}, {90, 30, 0.25f}, {70, 30, 0.25f}};
    const std::vector<glm::uvec3> t = {{0, 1, 2}, {0, 2, 3}};
    for (SimdLevel level : supportedLevels()) {
        Rasterizer r(level);
        Framebuffer fb(kWidth, kHeight, {.stencil = true});
        fb.clearDepth(0.75f);
        fb.clearStencil(9);
        PipelineState s;
        s.cull = CullMode::None;
        r.draw(fb, s, test::windowDraw(fb, p, t));
        const auto inQuad = [](int x, int y) { return x >= 70 && x < 90 && y >= 10 && y < 30; };
        const std::vector<float> depth = fb.depthImage();
        const std::vector<uint8_t> stencil = fb.stencilImage();
        for (int y = 0; y < kHeight; ++y) {
            for (int x = 0; x < kWidth; ++x) {
                const size_t k = size_t(y) * kWidth + size_t(x);
                REQUIRE(depth[k] == (inQuad(x, y) ? 0.25f : 0.75f));
                REQUIRE(stencil[k] == 9);
            }
        }
        // A clear after the draw hides it again, in the images and in the resolved storage.
        fb.clearDepth(0.5f);
        const FramebufferView view = fb.view();
        for (int y = 0; y < kHeight; ++y) {
            for (int x = 0; x < kWidth; ++x) REQUIRE(view.depth[fb.index(x, y)] == 0.5f);
        }
        r.draw(fb, s, test::windowDraw(fb, p, t));
        const size_t inside = fb.index(80, 20), outside = fb.index(150, 100);
        const raster::BufferStorage<float> storage = fb.takeDepth();
        CHECK(storage[inside] == 0.25f);
        CHECK(storage[outside] == 0.5f);
    }
}
