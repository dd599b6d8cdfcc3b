#include "shadows/projected/occluder_texture.h"

#include "raster/rasterizer.h"
#include "shadows/projected/occluder_view.h"
#include "shadows/world_draw.h"

namespace shadowlab {

std::vector<float> OccluderTexture::image() const {
    std::vector<float> rows = map.image();
    for (float& texel : rows) texel = texel < 1.0f ? 0.0f : 1.0f;
    return rows;
}

OccluderTexture renderOccluderTexture(const WorldGeometry& casters, std::span<const uint32_t> occluders,
                                      const Light& light, int resolution, raster::SimdLevel simd) {
    OccluderTexture texture;
    if (occluders.empty()) return texture;   // drawWorld would draw every triangle
    DepthMap& map = texture.map;
    map.view = fitOccluderView(casters, occluders, light, resolution);
    map.size = resolution;
    map.tilesX = (resolution + raster::kTileSize - 1) / raster::kTileSize;
    const glm::mat4 clipFromWorld(map.view.clipFromWorld());
    map.texelFromWorld = texelFromWorldOf(clipFromWorld, resolution);
    map.worldFromTexel = glm::inverse(map.texelFromWorld);
    raster::Framebuffer framebuffer(resolution, resolution);   // depth cleared to 1: nothing covered
    raster::PipelineState state;
    state.cull = raster::CullMode::None;   // an occluder covers the light with either side
    state.output = raster::FragmentOutput::DepthOnly;
    raster::Rasterizer rasterizer(simd);
    drawWorld(rasterizer, framebuffer, state, casters, clipFromWorld, occluders);
    map.depth = framebuffer.takeDepth();
    return texture;
}

}  // namespace shadowlab
