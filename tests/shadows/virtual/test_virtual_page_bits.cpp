// A virtual shadow map's pages are an ordinary shadow map of the same texels, bit for bit,
// whichever pages are drawn and in what order: each page is drawn as a window of its cell's
// map (page_rendering.h), so on the sun case every texel of every page of a cell equals the
// texel an ordinary map of that cell, drawn whole in one pass with every caster, holds
// there. At a coarse level the casters lie inside the cell; at a fine one the ground reaches
// far past it, so its triangles are clipped at the guard band, the same way in both.
#include <doctest/doctest.h>

#include <cstring>
#include <vector>

#include "scenes/bounds.h"
#include "scenes/prepared_scene.h"
#include "scenes/scene_file.h"
#include "shadows/virtual/page_rendering.h"

using namespace shadowlab;
using namespace shadowlab::vsm;

namespace {

struct CellComparison {
    size_t texels = 0, differing = 0, covered = 0;   // covered: a caster's depth, not the clear
};

// Every page of cell (cx, cy) of `level`, drawn as the virtual map draws them, against the
// cell's ordinary map.
CellComparison comparePagesWithMap(const PreparedScene& prepared, const ClipmapSettings& c, int level, int32_t cx,
                                   int32_t cy, raster::SimdLevel simd) {
    const LightFrame frame = LightFrame::towards(glm::dvec3(prepared.scene().lights[0].direction));
    const std::vector<Aabb> boxes = instanceBounds(prepared.scene(), prepared.world());
    const vsm::DepthRange range = depthRangeOf(boxes, frame);
    const int cell = cellTexels(c), pagesPerCell = cell / c.pageTexels;
    std::vector<PageKey> keys;
    std::vector<int32_t> physical;
    for (int y = 0; y < pagesPerCell; ++y) {
        for (int x = 0; x < pagesPerCell; ++x) {
            keys.push_back({level, cx * pagesPerCell + x, cy * pagesPerCell + y});
            physical.push_back(int32_t(physical.size()));
        }
    }
    const raster::PolygonOffset offset{1.5f, 2.0f};
    PageDrawing drawing;
    PagePool pool{c.pageTexels, {}};
    renderPages(prepared, boxes, frame, c, range, keys, physical, offset, simd, drawing, pool);

    const DepthMap map = renderDepthMap(prepared.world(), pageView(frame, c, range, keys[0]).cell,
                                        {cell, DepthLayer::First, offset, {}}, simd);
    CellComparison out;
    for (size_t k = 0; k < keys.size(); ++k) {
        const int x0 = (keys[k].x - cx * pagesPerCell) * c.pageTexels, y0 = (keys[k].y - cy * pagesPerCell) * c.pageTexels;
        for (int y = 0; y < c.pageTexels; ++y) {
            for (int x = 0; x < c.pageTexels; ++x) {
                const float page = pool.at(physical[k], x, y), whole = map.at(x0 + x, y0 + y);
                out.texels += 1;
                out.differing += std::memcmp(&page, &whole, sizeof page) != 0;
                out.covered += whole < 1.0f;
            }
        }
    }
    return out;
}

}  // namespace

TEST_CASE("virtual pages: every page equals an ordinary shadow map of its cell, bit for bit") {
    Scene scene = loadScene(std::string(SHADOWLAB_SOURCE_DIR) + "/assets/scenes/hard/sun.json");
    const PreparedScene prepared(std::move(scene));
    // Cells of 512 texels in pages of 64: level 3 is 16 m a side (3 cm texels), level -2
    // 0.5 m (1 mm texels).
    const ClipmapSettings c{.resolution = 512, .pageTexels = 64, .firstLevel = -2, .lastLevel = 3};
    struct Case {
        int level;
        int32_t cx, cy;
        raster::SimdLevel simd;
    };
    for (const Case& k : {Case{3, 0, 0, raster::SimdLevel::Scalar}, Case{3, -1, -1, raster::bestSimdLevel()},
                          Case{-2, 0, 0, raster::bestSimdLevel()}, Case{-2, -1, 0, raster::SimdLevel::Scalar}}) {
        CAPTURE(k.level);
        CAPTURE(k.cx);
        CAPTURE(k.cy);
        const CellComparison r = comparePagesWithMap(prepared, c, k.level, k.cx, k.cy, k.simd);
        CHECK(r.differing == 0);
        CHECK(r.covered > r.texels / 20);   // the casters are there to compare
    }
}

TEST_CASE("raster: a framebuffer drawn as a window must lie inside a viewport the rasterizer can take") {
    Scene scene = loadScene(std::string(SHADOWLAB_SOURCE_DIR) + "/assets/scenes/hard/sun.json");
    const PreparedScene prepared(std::move(scene));
    const ClipmapSettings c{.resolution = 256, .pageTexels = 64, .firstLevel = 0, .lastLevel = 0};
    const LightView view = pageView(LightFrame{}, c, {}, {0, 0, 0}).cell;
    for (const raster::ViewportWindow& w : {raster::ViewportWindow{256, 256, 200, 0}, raster::ViewportWindow{0, 0, 8, 0},
                                            raster::ViewportWindow{raster::kMaxViewport * 2, 64, 0, 0},
                                            raster::ViewportWindow{256, 256, -64, 0}}) {
        CHECK_THROWS_WITH_AS(renderDepthMap(prepared.world(), view, {64, DepthLayer::First, {}, w}, raster::SimdLevel::Scalar),
                             doctest::Contains("window inside a viewport"), std::invalid_argument);
    }
}
