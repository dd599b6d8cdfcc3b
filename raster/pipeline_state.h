// The fixed-function state of a draw: culling, depth, stencil, polygon offset, colour
// mask and blending, as OpenGL defines them (OpenGL 4.6 core, sections 14.6.5 "Depth
// Offset", 17.3.3 "Stencil Test", 17.3.4 "Depth Buffer Test", 17.3.6 "Blending").
// Plain data only: the per-ISA kernels include this header.
#pragma once

#include <cstdint>

#include "raster/texture_wrap.h"

namespace shadowlab::raster {

enum class CullMode : uint8_t { None, Back, Front };

// Front faces wind counter-clockwise in normalised device coordinates (conventions.md).
enum class CompareFunc : uint8_t { Never, Less, Equal, LessEqual, Greater, NotEqual, GreaterEqual, Always };

enum class StencilOp : uint8_t { Keep, Zero, Replace, Increment, Decrement, IncrementWrap, DecrementWrap, Invert };

struct StencilFace {
    CompareFunc func = CompareFunc::Always;
    StencilOp stencilFail = StencilOp::Keep;   // stencil test failed
    StencilOp depthFail = StencilOp::Keep;     // stencil passed, depth failed
    StencilOp depthPass = StencilOp::Keep;     // both passed
    uint8_t reference = 0;
    uint8_t compareMask = 0xff;                // ANDed with reference and stored value before comparing
    uint8_t writeMask = 0xff;                  // bits the operation may change
};

struct StencilState {
    bool enabled = false;
    StencilFace front, back;                   // two-sided stencil: chosen by the triangle's facing
};

struct DepthState {
    bool test = true;
    bool write = true;
    CompareFunc func = CompareFunc::Less;
};

// Offset added to every fragment's window depth: factor * m + units * r, where m is the
// triangle's largest depth slope max(|dz/dx|, |dz/dy|) and r the smallest resolvable
// difference of a float depth buffer at the triangle's largest depth (2^(e - 23)).
struct PolygonOffset {
    float factor = 0.0f;
    float units = 0.0f;
};

enum class BlendEquation : uint8_t { Add, Subtract, ReverseSubtract, Min, Max };
enum class BlendFactor : uint8_t {
    Zero, One, SrcColor, OneMinusSrcColor, DstColor, OneMinusDstColor,
    SrcAlpha, OneMinusSrcAlpha, DstAlpha, OneMinusDstAlpha
};

// result = equation(src * srcFactor, dst * dstFactor); Min and Max ignore the factors.
struct BlendState {
    bool enabled = false;
    BlendEquation equation = BlendEquation::Add;
    BlendFactor srcFactor = BlendFactor::One;
    BlendFactor dstFactor = BlendFactor::Zero;
};

// What a covered fragment that passes the tests writes besides depth and stencil.
enum class FragmentOutput : uint8_t {
    DepthOnly,      // shadow maps, z-prepass, stencil volumes: no varyings are interpolated
    PrimitiveId,    // visibility buffer: the triangle's id, for a G-buffer built afterwards
    ConstantColor,  // the draw's colour (planar shadows, penumbra weights, debug views)
    VaryingColor,   // varyings 0..3 interpolated perspective-correctly as RGBA
    // Every fragment that passes the tests is appended to its tile's list (pixel, depth,
    // primitive id), in the order of the tile's triangles, which is submission order: the
    // light's view of translucent casters for volumetric shadow maps, all layers at once.
    FragmentList,
};

// The alpha test of a cut-out (foliage cards), before the depth and stencil tests: a
// fragment whose alpha is below the cutoff is discarded. Alpha is read from a texture at the
// draw's varyings 0 and 1, interpolated perspective-correctly as (u, v): the nearest texel of
// the coordinates wrapped by `wrap` (raster/nearest_texel.inl), u to the right and v up (row
// 0 of `alpha` is the texture's top, at v = 1). Off while `alpha` is null.
struct AlphaTest {
    const float* alpha = nullptr;   // width * height values, row-major
    int width = 0, height = 0;
    float cutoff = 0.5f;
    UvWrap wrap{};
};

// The framebuffer as a window of a larger viewport, as OpenGL draws with glViewport at a
// negative offset and the scissor at the framebuffer: vertices are placed, snapped, clipped
// and set up in the viewport's pixels, and the framebuffer holds viewport pixels [x, x +
// width) x [y, y + height) (row 0 at the top). Two windows of one viewport, and the viewport
// drawn whole, so give the same bits to every pixel they share: a virtual shadow map's pages
// are windows of one map (shadows/virtual/page_rendering.h). viewportWidth 0: the viewport is
// the framebuffer itself (x = y = 0).
struct ViewportWindow {
    int viewportWidth = 0, viewportHeight = 0;
    int x = 0, y = 0;
};

struct PipelineState {
    CullMode cull = CullMode::Back;
    bool clipFar = true;            // false for an infinite far projection (shadow volumes)
    bool conservative = false;      // outer-conservative coverage: every pixel the triangle touches
    DepthState depth;
    StencilState stencil;
    PolygonOffset offset;
    FragmentOutput output = FragmentOutput::DepthOnly;
    uint8_t colorWriteMask = 0xf;   // bit k enables channel k (R, G, B, A)
    BlendState blend;
    AlphaTest alphaTest;
    ViewportWindow window;
};

}  // namespace shadowlab::raster
