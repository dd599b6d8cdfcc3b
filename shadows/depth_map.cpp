#include "shadows/depth_map.h"

#include <optional>

#include <tbb/parallel_for.h>

#include "raster/rasterizer.h"
#include "shadows/world_draw.h"

namespace shadowlab {

SettingsTable<int> mapResolutionTable(const std::string& help) {
    return SettingsTable<int>().integer("resolution", itself<int>(), kMinMapResolution, kMaxMapResolution, help);
}
namespace {

// One depth-only pass into `depth`'s memory, `draw(rasterizer, framebuffer, state)` drawing
// the casters. Without culling it keeps the nearest surface of any facing (the first depth:
// a one-sided or open occluder casts whichever side the light sees); culling front faces
// keeps the back faces (the second depth, RTR 7.4).
template <class Draw>
void drawDepthLayer(const DepthMapSettings& settings, raster::CullMode cull, raster::Rasterizer& rasterizer,
                    const Draw& draw, raster::BufferStorage<float>& depth) {
    raster::Framebuffer framebuffer(settings.size, settings.size, {}, {.depth = std::move(depth)});   // cleared to 1
    raster::PipelineState state;
    state.cull = cull;
    state.offset = settings.offset;
    state.output = raster::FragmentOutput::DepthOnly;
    state.window = settings.window;
    draw(rasterizer, framebuffer, state);
    depth = framebuffer.takeDepth();
}

template <class Draw>
DepthMap depthMapOf(const LightView& view, const DepthMapSettings& settings, raster::SimdLevel simd, const Draw& draw,
                    DepthMap map, raster::Rasterizer* kept) {
    std::optional<raster::Rasterizer> own;
    raster::Rasterizer& rasterizer = kept ? *kept : own.emplace(simd);
    map.size = settings.size;
    map.tilesX = (settings.size + raster::kTileSize - 1) / raster::kTileSize;
    map.view = view;
    map.texelFromWorld = texelFromWorldOf(glm::mat4(view.clipFromWorld()), settings.size, settings.window);
    map.worldFromTexel = glm::inverse(map.texelFromWorld);
    switch (settings.layer) {
        case DepthLayer::First:
            drawDepthLayer(settings, raster::CullMode::None, rasterizer, draw, map.depth);
            break;
        case DepthLayer::Second:
            drawDepthLayer(settings, raster::CullMode::Front, rasterizer, draw, map.depth);
            break;
        case DepthLayer::Midpoint: {
            // Woo's midpoint: halfway (in window depth) between the first and second surface.
            // Where there is no back face the second depth is the cleared 1, so a single-sided
            // receiver such as a ground plane stays in front of its own entry.
            drawDepthLayer(settings, raster::CullMode::None, rasterizer, draw, map.depth);
            raster::BufferStorage<float> second;
            drawDepthLayer(settings, raster::CullMode::Front, rasterizer, draw, second);
            for (size_t k = 0; k < map.depth.size(); ++k) map.depth[k] = 0.5f * (map.depth[k] + second[k]);
            break;
        }
    }
    return map;
}

}  // namespace

std::vector<float> DepthMap::image() const {
    std::vector<float> rows;
    image(rows);
    return rows;
}

void DepthMap::image(std::vector<float>& rows) const {
    rows.resize(size_t(size) * size_t(size));
    tbb::parallel_for(0, size, [&](int y) {
        for (int x = 0; x < size; ++x) rows[size_t(y) * size_t(size) + size_t(x)] = at(x, y);
    });
}

glm::dmat4 texelFromClip(int size, const raster::ViewportWindow& in) {
    // x_texel = (x_ndc + 1) w / 2 - x0, y_texel = (1 - y_ndc) h / 2 - y0 (row 0 on top),
    // z = (z_ndc + 1) / 2: raster/window.h's toWindow, in the window's texels.
    const double hx = 0.5 * (in.viewportWidth ? in.viewportWidth : size);
    const double hy = 0.5 * (in.viewportWidth ? in.viewportHeight : size);
    glm::dmat4 window(1.0);
    window[0][0] = hx, window[1][1] = -hy, window[2][2] = 0.5;
    window[3] = glm::dvec4(hx - in.x, hy - in.y, 0.5, 1.0);
    return window;
}

glm::dmat4 texelFromWorldOf(const glm::mat4& clipFromWorld, int size, const raster::ViewportWindow& window) {
    return texelFromClip(size, window) * glm::dmat4(clipFromWorld);
}

DepthMap renderDepthMap(const WorldGeometry& world, const LightView& view, const DepthMapSettings& settings,
                        raster::SimdLevel simd, DepthMap memory,
                        raster::Rasterizer* rasterizer) {
    const glm::mat4 clipFromWorld(view.clipFromWorld());
    return depthMapOf(view, settings, simd,
                      [&](raster::Rasterizer& r, raster::Framebuffer& fb, const raster::PipelineState& state) {
                          drawWorld(r, fb, state, world, clipFromWorld);
                      },
                      std::move(memory), rasterizer);
}

DepthMap renderDepthMap(const PreparedScene& prepared, const LightView& view, const DepthMapSettings& settings,
                        raster::SimdLevel simd, DepthMap memory,
                        raster::Rasterizer* rasterizer) {
    const glm::mat4 clipFromWorld(view.clipFromWorld());
    const WorldDraws& draws = preparedWorldDraws(prepared);
    return depthMapOf(view, settings, simd,
                      [&](raster::Rasterizer& r, raster::Framebuffer& fb, const raster::PipelineState& state) {
                          drawWorld(r, fb, state, prepared.world(), draws, clipFromWorld);
                      },
                      std::move(memory), rasterizer);
}

DepthMap renderDepthMap(const WorldGeometry& world, std::span<const uint32_t> triangles, const LightView& view,
                        const DepthMapSettings& settings, raster::SimdLevel simd, DepthMap memory,
                        raster::Rasterizer* rasterizer) {
    const glm::mat4 clipFromWorld(view.clipFromWorld());
    return depthMapOf(view, settings, simd,
                      [&](raster::Rasterizer& r, raster::Framebuffer& fb, const raster::PipelineState& state) {
                          if (!triangles.empty()) drawWorld(r, fb, state, world, clipFromWorld, triangles);
                      },
                      std::move(memory), rasterizer);
}

}  // namespace shadowlab
