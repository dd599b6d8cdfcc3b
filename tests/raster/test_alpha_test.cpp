// The alpha test (pipeline_state.h, AlphaTest): a quad whose texture coordinates run across
// it covers exactly the pixels whose texel's alpha reaches the cutoff, the same bytes at
// every SIMD level, for depth-only and primitive-id output; and bad use is refused.
#include <doctest/doctest.h>

#include "tests/raster/raster_test_util.h"

using namespace shadowlab;
using namespace shadowlab::test;

namespace {

// An 8 x 2 texture: columns alternate solid (0.9) and hole (0.2); the bottom row is all solid.
const std::vector<float> kAlpha = {0.9f, 0.2f, 0.9f, 0.2f, 0.9f, 0.2f, 0.9f, 0.2f,
                                   0.9f, 0.9f, 0.9f, 0.9f, 0.9f, 0.9f, 0.9f, 0.9f};

// A 64 x 32 pixel quad at (16, 16) in window space, u across x and v up y (row 0 on top).
struct Quad {
    std::vector<glm::vec3> positions = {{16, 48, 0.5f}, {80, 48, 0.5f}, {80, 16, 0.5f}, {16, 16, 0.5f}};
    std::vector<float> uvs = {0, 0, 1, 0, 1, 1, 0, 1};
    std::vector<glm::uvec3> triangles = {{0, 1, 2}, {0, 2, 3}};
};

std::vector<uint32_t> drawQuad(raster::SimdLevel level, raster::FragmentOutput output) {
    raster::Framebuffer fb(96, 64, {.primitiveId = true});
    fb.clearPrimitiveId(99);
    raster::PipelineState state;
    state.cull = raster::CullMode::None;
    state.output = output;
    state.alphaTest = {kAlpha.data(), 8, 2, 0.5f};
    const Quad quad;
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
    state.alphaTest = {kAlpha.data(), 8, 2, 0.5f};
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
