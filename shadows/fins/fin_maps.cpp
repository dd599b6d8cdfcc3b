#include "shadows/fins/fin_maps.h"

#include "raster/rasterizer.h"

namespace shadowlab {
namespace {

// Where no inner fin lies, the min-combined weight keeps this: above every weight (<= 1).
constexpr float kInnerWeightClear = 1.0f;
constexpr float kOuterWeightClear = 0.0f;

raster::DrawCall finDraw(const FinPrimitives& fins, std::span<const glm::uvec3> triangles, const LightView& view) {
    raster::DrawCall call;
    call.vertices.positions = fins.positions;
    call.vertices.varyings = fins.weights;
    call.vertices.varyingCount = 1;
    call.triangles = triangles;
    call.clipFromObject = glm::mat4(view.clipFromWorld());
    return call;
}

// The nearest fin's depth: an ordinary depth pass. Fins are seen from both sides.
raster::PipelineState finDepthState() {
    raster::PipelineState state;
    state.cull = raster::CullMode::None;
    return state;
}

// Every fin fragment blends its weight into R with min or max, whatever its depth.
raster::PipelineState finWeightState(FinKind kind) {
    raster::PipelineState state;
    state.cull = raster::CullMode::None;
    state.depth = {.test = false, .write = false, .func = raster::CompareFunc::Always};
    state.output = raster::FragmentOutput::VaryingColor;
    state.colorWriteMask = 0x1;
    state.blend = {.enabled = true,
                   .equation = kind == FinKind::Inner ? raster::BlendEquation::Min : raster::BlendEquation::Max};
    return state;
}

}  // namespace

PenumbraMap renderPenumbraMap(const FinPrimitives& fins, std::span<const glm::uvec3> triangles,
                              const LightView& view, int size, FinKind kind, raster::SimdLevel simd) {
    raster::Framebuffer framebuffer(size, size, {.color = true});
    framebuffer.clearDepth(1.0f);
    framebuffer.clearColor(glm::vec4(kind == FinKind::Inner ? kInnerWeightClear : kOuterWeightClear));
    const raster::DrawCall call = finDraw(fins, triangles, view);
    raster::Rasterizer rasterizer(simd);
    rasterizer.draw(framebuffer, finDepthState(), call);
    rasterizer.draw(framebuffer, finWeightState(kind), call);
    return {size, framebuffer.tilesX(), framebuffer.takeDepth(), framebuffer.takeColor(0)};
}

double lightDistanceOfDepth(const LightView& view, double windowDepth) {
    // z_ndc = -[2][2] + [3][2] / L for a view-space z = -L (glm::frustumRH_NO), solved for L.
    const double zNdc = 2.0 * windowDepth - 1.0;
    return view.clipFromView[3][2] / (zNdc + view.clipFromView[2][2]);
}

}  // namespace shadowlab
