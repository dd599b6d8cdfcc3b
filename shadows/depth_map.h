// The shadow map itself (Real-Time Rendering, 4th ed., section 7.4): the depth of the
// nearest surface seen from the light through every texel, rendered by the rasterizer
// with depth-only output. Besides the ordinary first-depth map it can keep the second
// depth (back faces only, Wang and Molnar's second-depth shadow map) or the midpoint of
// the two (Woo's dual-depth "midpoint" map), both from section 7.4 and Figure 7.14.
//
// Texel space: texel (i, j) covers [i, i+1) x [j, j+1) with its centre at (i+0.5, j+0.5)
// and row 0 at the top, as every image (conventions.md); depth is OpenGL window depth in
// [0, 1], 1 where nothing was drawn.
#pragma once

#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "raster/fixed_point.h"
#include "raster/framebuffer.h"
#include "raster/pipeline_state.h"
#include "raster/rasterizer.h"
#include "raster/tile_kernels.h"
#include "scenes/prepared_scene.h"
#include "scenes/scene.h"
#include "shadows/light_view.h"
#include "shadows/settings_table.h"
#include "shadows/texel_index.h"

namespace shadowlab {

enum class DepthLayer { First, Second, Midpoint };

// The texels per side a technique's maps may have. A map is drawn as one viewport, so the
// rasterizer's limit (fixed_point.h) is the upper one.
inline constexpr int kMinMapResolution = 16, kMaxMapResolution = raster::kMaxViewport;

// The `resolution` row of a technique's table, for a member of its settings (whose default
// it keeps); `help` says which map.
SettingsTable<int> mapResolutionTable(const std::string& help);

struct DepthMap {
    int size = 0;                           // texels per side (square map)
    LightView view;
    // World -> (texel x, texel y, window depth, 1), with exactly the float matrix the
    // rasterizer used, so a lookup lands where the map's triangles were drawn.
    glm::dmat4 texelFromWorld{1.0};
    glm::dmat4 worldFromTexel{1.0};         // its inverse, for receiver planes and texel sizes
    // The rasterizer's depth buffer as it drew it, block-linear (raster::blockLinearIndex):
    // read in place, never copied to rows, so a lookup's neighbouring taps share a block.
    raster::BufferStorage<float> depth;
    int tilesX = 0;

    // The texel's depth; coordinates outside the map are clamped to its border.
    float at(int x, int y) const {
        x = x < 0 ? 0 : x >= size ? size - 1 : x;
        y = y < 0 ? 0 : y >= size ? size - 1 : y;
        return depth[raster::blockLinearIndex(x, y, tilesX)];
    }
    // Row-major, row 0 at the top: the map as an image (debug views, filtered maps); the
    // second form writes it into `rows`' memory (a kept buffer, technique_history.h).
    std::vector<float> image() const;
    void image(std::vector<float>& rows) const;
};

// The window transform of a size x size map: clip space -> (texel x, texel y, window depth,
// w); for a map drawn as a window of a larger viewport, that viewport's transform moved to
// the window.
glm::dmat4 texelFromClip(int size, const raster::ViewportWindow& window = {});
// The same after `clipFromWorld` (float, as drawn).
glm::dmat4 texelFromWorldOf(const glm::mat4& clipFromWorld, int size, const raster::ViewportWindow& window = {});

struct DepthMapSettings {
    int size = 2048;
    DepthLayer layer = DepthLayer::First;
    raster::PolygonOffset offset;           // slope-scaled bias, applied while drawing
    // The map as a window of a larger square viewport (pipeline_state.h): its texels then
    // have the bits of that viewport's, wherever it is drawn whole or in other windows.
    raster::ViewportWindow window;
};

// The world's triangles, cut-outs with their holes (world_draw.h). The map is drawn in
// `memory`'s depth buffer, reallocated only if it is too small, with `rasterizer` where given
// (at `simd`; its front-end buffers keep their memory), else a rasterizer of its own: a
// technique that keeps its maps and rasterizer between frames (technique_history.h,
// kept_raster.h) passes last frame's and allocates no map afresh.
DepthMap renderDepthMap(const WorldGeometry& world, const LightView& view, const DepthMapSettings& settings,
                        raster::SimdLevel simd, DepthMap memory = {},
                        raster::Rasterizer* rasterizer = nullptr);
// The same for a prepared scene's world, its draws grouped once for every map of every frame
// (preparedWorldDraws): what a technique drawing several maps a frame (cube faces,
// multi-sample's views) passes.
DepthMap renderDepthMap(const PreparedScene& prepared, const LightView& view, const DepthMapSettings& settings,
                        raster::SimdLevel simd, DepthMap memory = {},
                        raster::Rasterizer* rasterizer = nullptr);
// The same for some of the world's triangles (indices into world.triangles, ascending; none
// drawn when empty), as the fins' hard maps draw one layer's objects.
DepthMap renderDepthMap(const WorldGeometry& world, std::span<const uint32_t> triangles, const LightView& view,
                        const DepthMapSettings& settings, raster::SimdLevel simd, DepthMap memory = {},
                        raster::Rasterizer* rasterizer = nullptr);

}  // namespace shadowlab
