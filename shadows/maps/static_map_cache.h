// Cached shadow maps of static casters (docs/cached-shadow-maps.md): a map of the
// casters that never moved is kept across frames, and each frame's map is a copy of it with
// the casters that move drawn over the copy, as engines cache shadows (Unity HDRP's cached
// shadows with "Always Draw Dynamic": the static casters' map rendered on demand, the dynamic
// casters drawn each frame over a copy of it; HDRP manual, "Shadows in HDRP", and
// HDAdditionalLightData.alwaysDrawDynamicShadows).
//
// Why the result equals a fresh map bit for bit: a texel's depth is the minimum over the
// fragments every caster draws there (the depth test keeps the nearest), each fragment's
// depth depends only on its triangle and the texel, and a minimum does not depend on the
// order or grouping of its terms. So min(static map, dynamic casters' depths) = the map of
// all casters. The rasterizer draws a window of a viewport with that viewport's bits
// (raster::ViewportWindow), so a rectangle drawn alone equals the same texels drawn whole.
// The midpoint layer averages two layers and is no such minimum: it is not cached.
//
// Which casters are dynamic the cache learns from the frames: an instance whose
// worldFromObject changed since the last frame becomes dynamic for good. The static map then
// loses it: the texels its former bounds cover in the light's view (the projection of its
// box's corners, outward to whole texels) are drawn again from the static casters alone,
// since a caster changes only texels its silhouette covers (as a virtual map invalidates
// pages, shadows/virtual/page_invalidation.h). Another view (the light moved, or the fit
// changed: with the default fit to the visible receivers, whenever the camera or the
// receivers' bounds move) invalidates the whole map.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/bounds.h"
#include "scenes/prepared_scene.h"
#include "shadows/depth_map.h"
#include "shadows/kept_raster.h"

namespace shadowlab {

// Texels [x0, x1) x [y0, y1) of a map; empty when x0 >= x1 or y0 >= y1.
struct MapRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool empty() const { return x0 >= x1 || y0 >= y1; }
    int64_t area() const { return empty() ? 0 : int64_t(x1 - x0) * int64_t(y1 - y0); }
};

// The smallest rectangle holding both.
MapRect unite(const MapRect& a, const MapRect& b);

// The texels of `map` that a caster inside `box` can cover: its corners' projection, outward
// to whole texels plus one (the rasterizer snaps vertices to a sub-texel grid), clamped to
// the map; the whole map where a corner lies at or behind a perspective view's apex plane.
MapRect texelsUnder(const Aabb& box, const DepthMap& map);

// What the cache keeps between frames (technique_history.h): a value, copied with the history.
struct StaticMapCache {
    DepthMap staticMap;                        // the static casters' depths, drawn in staticMap.view
    bool valid = false;                        // staticMap holds this view's static casters
    uint64_t geometryVersion = 0;              // PreparedScene::geometryVersion() at the last frame
    std::vector<glm::mat4> worldFromObject;    // per instance, at the last frame
    std::vector<Aabb> bounds;                  // per instance, at the last frame
    std::vector<uint8_t> dynamic;              // per instance: it has moved since the first frame
    std::vector<uint32_t> staticTriangles, dynamicTriangles;   // indices into the world's, ascending
    DepthMap window;                           // a rectangle's texels, drawn alone (its memory kept)
    KeptRasterizer rasterizer;
};

// What a frame drew.
struct CachedMapStats {
    int64_t redrawnTexels = 0;      // texels of the static map drawn again (all of them on a new view)
    int64_t dynamicTexels = 0;      // texels the dynamic casters were drawn over
    size_t staticTriangles = 0;     // static triangles drawn (0 in a frame that redrew nothing)
    size_t dynamicTriangles = 0;    // dynamic triangles drawn
    size_t dynamicInstances = 0;
    MapRect redrawn, dynamic;       // where they were drawn (the union of the static map's redrawn rectangles)
};

// The frame's map of `casters` in `view`: the static map, updated as above, then, where
// some caster is dynamic, copied into `out`'s memory with the dynamic casters drawn over the
// copy (cachedFrameMap says which). `geometryVersion` is the prepared scene's (the camera's
// scene, whose moves the casters follow). Throws std::invalid_argument for the midpoint layer.
CachedMapStats drawCachedMap(const PreparedScene& casters, uint64_t geometryVersion, const LightView& view,
                             const DepthMapSettings& settings, raster::SimdLevel simd, StaticMapCache& cache,
                             DepthMap& out);

// The frame's map drawCachedMap made: `out`, or the static map itself while no caster is
// dynamic (no copy is made then).
inline const DepthMap& cachedFrameMap(const StaticMapCache& cache, const DepthMap& out) {
    return cache.dynamicTriangles.empty() ? cache.staticMap : out;
}

}  // namespace shadowlab
