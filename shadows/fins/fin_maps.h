// The light-space maps of shadow fins (Cai et al. 2006, sections 3.2 and 3.3, Figure 3
// left), all seen from the centre of the disk light through the same frustum, whose axis is
// the light's normal (so its depth planes are parallel to the light's plane):
//
//   the hard shadow map of one layer: the depths of the layer's objects (depth_map.h with
//       the layer's triangles);
//   the inner and the outer penumbra map of one layer: for its fins, the depth of the
//       nearest fin (a depth-only pass) and the weight s_0 combined over overlapping fins
//       with min for inner fins and max for outer ones (section 3.3; EXT_blend_minmax,
//       here BlendEquation::Min and ::Max).
//
// Texel conventions are those of depth_map.h.
#pragma once

#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "raster/framebuffer.h"
#include "raster/tile_kernels.h"
#include "scenes/scene.h"
#include "shadows/depth_map.h"
#include "shadows/fins/fin_geometry.h"
#include "shadows/light_view.h"

namespace shadowlab {

enum class FinKind { Inner, Outer };

// Both planes block-linear, as the rasterizer drew them (raster::blockLinearIndex with
// tilesX), read in place.
struct PenumbraMap {
    int size = 0, tilesX = 0;
    raster::BufferStorage<float> depth;    // window depth of the nearest fin, 1 where no fin covers
    raster::BufferStorage<float> weight;   // min (inner) or max (outer) of s_0; meaningless where depth = 1

    size_t index(int x, int y) const { return raster::blockLinearIndex(x, y, tilesX); }
    bool covered(int x, int y) const { return depth[index(x, y)] < 1.0f; }
};

// The fin triangles `triangles` (indices into fins.positions) drawn into a size x size map.
PenumbraMap renderPenumbraMap(const FinPrimitives& fins, std::span<const glm::uvec3> triangles,
                              const LightView& view, int size, FinKind kind, raster::SimdLevel simd);

// The distance L from the light's plane of a window depth of `view` (perspective).
double lightDistanceOfDepth(const LightView& view, double windowDepth);

}  // namespace shadowlab
