#include "shadows/fins/fins_debug.h"

#include <cstdio>

#include "raster/rasterizer.h"

namespace shadowlab {
namespace {

std::string layerPrefix(int layer) {
    char name[32];
    std::snprintf(name, sizeof name, "layer-%02d-", layer);
    return name;
}

// Adds 1 per fin fragment into R, whatever its depth, seen from both sides.
raster::PipelineState coverageCountState() {
    raster::PipelineState state;
    state.cull = raster::CullMode::None;
    state.depth = {.test = false, .write = false, .func = raster::CompareFunc::Always};
    state.output = raster::FragmentOutput::ConstantColor;
    state.colorWriteMask = 0x1;
    state.blend = {.enabled = true, .equation = raster::BlendEquation::Add, .srcFactor = raster::BlendFactor::One,
                   .dstFactor = raster::BlendFactor::One};
    return state;
}

}  // namespace

FinDebug::FinDebug(std::filesystem::path directory, const std::string& technique, const LightView& view)
    : debug_(std::move(directory), technique), view_(view) {}

void FinDebug::writePenumbraMap(const std::string& prefix, const PenumbraMap& map, float edgeWeight) const {
    const size_t texels = size_t(map.size) * size_t(map.size);
    std::vector<float> weight(texels, 0.0f), distance(texels, 0.0f);
    for (int y = 0; y < map.size; ++y) {
        for (int x = 0; x < map.size; ++x) {
            if (!map.covered(x, y)) continue;
            const size_t t = size_t(y) * size_t(map.size) + size_t(x);
            weight[t] = map.weight[map.index(x, y)];
            distance[t] = float(lightDistanceOfDepth(view_, map.depth[map.index(x, y)]));
        }
    }
    debug_.write(prefix + "weight", map.size, map.size, weight, 0.0f, edgeWeight);
    debug_.write(prefix + "depth", map.size, map.size, distance, float(view_.zNear), float(view_.zFar));
}

void FinDebug::writeLayer(int layer, const DepthMap& hard, const PenumbraMap* inner, const PenumbraMap& outer,
                          float edgeWeight, const GBuffer& gbuffer, const std::vector<float>& illuminance) const {
    if (!debug_.enabled()) return;
    const std::string prefix = layerPrefix(layer);
    debug_.write(prefix + "shadow-map", hard.size, hard.size, hard.image(), 0.0f, 1.0f);
    if (inner) writePenumbraMap(prefix + "inner-", *inner, edgeWeight);
    writePenumbraMap(prefix + "outer-", outer, edgeWeight);
    debug_.write(prefix + "illuminance", gbuffer.width, gbuffer.height, illuminance, 0.0f, 1.0f);
}

void FinDebug::writeFinCoverage(const Fins& fins, int size, raster::SimdLevel simd) const {
    if (!debug_.enabled()) return;
    raster::Framebuffer framebuffer(size, size, {.color = true});
    framebuffer.clearDepth(1.0f);
    framebuffer.clearColor(glm::vec4(0.0f));
    raster::Rasterizer rasterizer(simd);
    for (const FinPrimitives* kind : {&fins.inner, &fins.outer}) {
        rasterizer.draw(framebuffer, coverageCountState(),
                        raster::positionsDraw(kind->positions, kind->triangles, glm::mat4(view_.clipFromWorld())));
    }
    debug_.write("fin-coverage", size, size, framebuffer.colorImage(0), 0.0f, 4.0f);
}

void FinDebug::writePixelLayers(const GBuffer& gbuffer, const WorldGeometry& world,
                                const std::vector<int>& instanceLayer, int layerCount) const {
    if (!debug_.enabled()) return;
    std::vector<float> layer(gbuffer.pixelCount(), -1.0f);
    for (size_t k = 0; k < layer.size(); ++k) {
        if (gbuffer.hit[k]) layer[k] = float(instanceLayer[world.triangleInstance[gbuffer.triangle[k]]]);
    }
    debug_.write("layers", gbuffer.width, gbuffer.height, layer, -1.0f, float(layerCount - 1));
}

}  // namespace shadowlab
