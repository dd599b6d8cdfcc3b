// The projected shadow texture (RTR 4th ed., section 7.2): the occluders as the light sees
// them (occluder_view.h), a binary image, 0 where an occluder covers the texel centre and
// 1 elsewhere. It is drawn by the rasterizer, depth only: a texel is covered where the
// depth is below the cleared 1. Texel space is the depth map's (depth_map.h).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "shadows/depth_map.h"
#include "scenes/scene.h"

namespace shadowlab {

struct OccluderTexture {
    DepthMap map;                       // the occluders' depths; covered where < 1
    bool empty() const { return map.size == 0; }
    bool covered(int x, int y) const { return map.at(x, y) < 1.0f; }
    // Row-major, row 0 at the top: 0 covered, 1 open (the debug image).
    std::vector<float> image() const;
};

// The occluders are triangles of `casters`; with none the texture is empty (size 0,
// nothing covered). Throws as fitOccluderView. The texture is drawn in `memory`'s map (last
// frame's, technique_history.h), reallocated only to grow, with `rasterizer` where given
// (renderDepthMap).
OccluderTexture renderOccluderTexture(const WorldGeometry& casters, std::span<const uint32_t> occluders,
                                      const Light& light, int resolution, raster::SimdLevel simd,
                                      OccluderTexture memory = {}, raster::Rasterizer* rasterizer = nullptr);

}  // namespace shadowlab
