#include "shadows/projected/occluder_texture.h"

#include <utility>

#include "shadows/projected/occluder_view.h"

namespace shadowlab {

std::vector<float> OccluderTexture::image() const {
    std::vector<float> rows = map.image();
    for (float& texel : rows) texel = texel < 1.0f ? 0.0f : 1.0f;
    return rows;
}

OccluderTexture renderOccluderTexture(const WorldGeometry& casters, std::span<const uint32_t> occluders,
                                      const Light& light, int resolution, raster::SimdLevel simd,
                                      OccluderTexture memory, raster::Rasterizer* rasterizer) {
    OccluderTexture texture = std::move(memory);
    if (occluders.empty()) {   // drawWorld would draw every triangle
        texture.map.size = 0;  // its memory kept for a later frame
        return texture;
    }
    // Depth only, no culling (an occluder covers the light with either side), no offset: a
    // texel is covered where the depth is below the cleared 1.
    const LightView view = fitOccluderView(casters, occluders, light, resolution);
    texture.map = renderDepthMap(casters, occluders, view, {resolution, DepthLayer::First, {}, {}}, simd,
                                 std::move(texture.map), rasterizer);
    return texture;
}

}  // namespace shadowlab
