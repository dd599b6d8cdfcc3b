// The alpha test (pipeline_state.h, AlphaTest): a quad whose texture coordinates run across
// it covers exactly the pixels whose texel's alpha reaches the cutoff, for each wrap mode
// (raster/nearest_texel.inl), the same bytes at every SIMD level, for depth-only and
// primitive-id output; and bad use is refused.
#include <doctest/doctest.h>

#include "tests/raster/raster_test_util.h"

using namespace shadowlab;
using namespace shadowlab::test;

namespace {

// An 8 x 2 texture: columns alternate solid (0.9) and hole (0.2); the bottom row is all solid.
const std::vector<float> kAlpha = {0.9f, 0.2f, 0.9f, 0.2f, 0.9f, 0.2f, 0.9f, 0.2f,
                                   0.9f, 0.9f, 0.9f, 0.9f, 0.9f, 0.9f, 0.9f, 0.9f};

const raster::AlphaTest kColumns = {kAlpha.data(), 8, 2, 0.5f, {}};

// A 64 x 32 pixel quad at (16, 16) in window space, u across x and v up y (row 0 on top).
struct Quad {
    std::vector<glm::vec3> positions = {{16, 48, 0.5f}, {80, 48, 0.5f}, {80, 16, 0.5f}, {16, 16, 0.5f}};
    std::vector<float> uvs = {0, 0, 1, 0, 1, 1, 0, 1};
    std::vector<glm::uvec3> triangles = {{0, 1, 2}, {0, 2, 3}};
};

std::vector<uint32_t> drawQuad(raster::SimdLevel level, raster::FragmentOutput output,
                               const raster::AlphaTest& test = kColumns, const Quad& quad = {}) {
    raster::Framebuffer fb(96, 64, {.primitiveId = true});
    fb.clearPrimitiveId(99);
    raster::PipelineState state;
    state.cull = raster::CullMode::None;
    state.output = output;
    state.alphaTest = test;
    raster::DrawCall call = windowDraw(fb, quad.positions, quad.triangles);
    call.vertices.varyings = quad.uvs;
    call.vertices.varyingCount = 2;
    raster::Rasterizer(level).draw(fb, state, call);
    if (output == raster::FragmentOutput::PrimitiveId) return fb.primitiveIdImage();
    std::vector<uint32_t> drawn;
    for (float z : fb.depthImage()) drawn.push_back(z < 1.0f ? 1 : 99);
    return drawn;
}

}  // namespace

TEST_CASE("the alpha test keeps exactly the pixels whose texel reaches the cutoff") {
    const std::vector<uint32_t> ids = drawQuad(raster::SimdLevel::Scalar, raster::FragmentOutput::PrimitiveId);
    int kept = 0;
    for (int j = 0; j < 64; ++j) {
        for (int i = 0; i < 96; ++i) {
            const bool onQuad = i >= 16 && i < 80 && j >= 16 && j < 48;
            // 8 pixels per texel across, 16 per texel down; the top texel row (v > 0.5) has holes.
            const int column = (i - 16) / 8, row = (j - 16) / 16;
            const bool solid = onQuad && (row == 1 || column % 2 == 0);
            INFO("pixel " << i << ", " << j);
            CHECK((ids[size_t(j) * 96 + size_t(i)] != 99) == solid);
            kept += solid;
        }
    }
    CHECK(kept == 64 * 16 + 32 * 16);
}

TEST_CASE("the alpha test is the same bytes at every SIMD level") {
    for (raster::FragmentOutput output : {raster::FragmentOutput::PrimitiveId, raster::FragmentOutput::DepthOnly}) {
        const std::vector<uint32_t> scalar = drawQuad(raster::SimdLevel::Scalar, output);
        for (raster::SimdLevel level : supportedLevels()) CHECK(drawQuad(level, output) == scalar);
    }
}

TEST_CASE("the alpha test needs a texture and texture coordinates") {
    raster::Framebuffer fb(32, 32);
    raster::PipelineState state;
    state.alphaTest = kColumns;
    const Quad quad;
    const raster::DrawCall withoutUvs = windowDraw(fb, quad.positions, quad.triangles);
    CHECK_THROWS_WITH_AS(raster::Rasterizer(raster::SimdLevel::Scalar).draw(fb, state, withoutUvs),
                         "draw: the alpha test needs a texture of at least 1 x 1 texels and varyings u, v",
                         std::invalid_argument);
    raster::DrawCall wrongIds = windowDraw(fb, quad.positions, quad.triangles);
    const std::vector<uint32_t> oneId = {7};
    wrongIds.primitiveIds = oneId;
    CHECK_THROWS_WITH_AS(raster::Rasterizer(raster::SimdLevel::Scalar).draw(fb, raster::PipelineState{}, wrongIds),
                         "draw: primitiveIds must hold one id per triangle", std::invalid_argument);
}

namespace {

// Wrap modes: one texel of four is solid, along u (a 4 x 1 texture, texel 0) or along v (a
// 1 x 4 texture, its bottom texel, row 3), so a pixel is solid where its wrapped coordinate
// s is below 0.25; the quad's coordinate runs over [-2, 2] along that axis.
const std::vector<float> kFirstOfFour = {0.9f, 0.2f, 0.2f, 0.2f};
const std::vector<float> kLastOfFour = {0.2f, 0.2f, 0.2f, 0.9f};

// By hand, at pixel i of 64 along u (u = -2 + (i + 0.5) / 16, a texel every 4 pixels):
// clamped, s < 0.25 up to u = 0.25; repeated, the first texel of every period; mirrored,
// periods [-2, -1] and [0, 1] run forward and [-1, 0] and [1, 2] backward.
bool solidAlongU(TextureWrap wrap, int i) {
    switch (wrap) {
        case TextureWrap::ClampToEdge: return i < 36;
        case TextureWrap::Repeat: return (i / 4) % 4 == 0;
        case TextureWrap::MirroredRepeat: return i < 4 || (i >= 28 && i < 36) || i >= 60;
    }
    return false;
}

constexpr TextureWrap kWraps[] = {TextureWrap::ClampToEdge, TextureWrap::Repeat, TextureWrap::MirroredRepeat};

}  // namespace

TEST_CASE("the alpha test wraps u and v as the texture's sampler says, at every SIMD level") {
    Quad alongU, alongV;
    alongU.uvs = {-2, 0, 2, 0, 2, 1, -2, 1};
    alongV.uvs = {0, -2, 1, -2, 1, 2, 0, 2};
    for (TextureWrap wrap : kWraps) {
        INFO("wrap mode " << int(wrap));
        const raster::AlphaTest testU = {kFirstOfFour.data(), 4, 1, 0.5f, {wrap, TextureWrap::ClampToEdge}};
        const raster::AlphaTest testV = {kLastOfFour.data(), 1, 4, 0.5f, {TextureWrap::ClampToEdge, wrap}};
        const std::vector<uint32_t> u = drawQuad(raster::SimdLevel::Scalar, raster::FragmentOutput::PrimitiveId, testU, alongU);
        const std::vector<uint32_t> v = drawQuad(raster::SimdLevel::Scalar, raster::FragmentOutput::PrimitiveId, testV, alongV);
        for (int j = 16; j < 48; ++j) {
            for (int i = 16; i < 80; ++i) {
                INFO("pixel " << i << ", " << j);
                const size_t at = size_t(j) * 96 + size_t(i);
                CHECK((u[at] != 99) == solidAlongU(wrap, i - 16));
                // v = 2 at the top, 8 pixels per unit: row k from the bottom is u's pixel 2k.
                CHECK((v[at] != 99) == solidAlongU(wrap, 2 * (47 - j)));
            }
        }
        for (raster::SimdLevel level : supportedLevels()) {
            for (raster::FragmentOutput output : {raster::FragmentOutput::PrimitiveId, raster::FragmentOutput::DepthOnly}) {
                CHECK(drawQuad(level, output, testU, alongU) == drawQuad(raster::SimdLevel::Scalar, output, testU, alongU));
                CHECK(drawQuad(level, output, testV, alongV) == drawQuad(raster::SimdLevel::Scalar, output, testV, alongV));
            }
        }
    }
}
