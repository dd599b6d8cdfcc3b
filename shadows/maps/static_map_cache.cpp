#include "shadows/maps/static_map_cache.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace shadowlab {
namespace {

bool sameView(const LightView& a, const LightView& b) {
    return a.viewFromWorld == b.viewFromWorld && a.clipFromView == b.clipFromView && a.orthographic == b.orthographic;
}

// Learns which instances move: those whose transform changed since the last frame become
// dynamic. Returns the former bounds of the instances that turned dynamic now (where the
// static map still holds them); `cache` then knows this frame's transforms and bounds.
std::vector<Aabb> learnDynamic(const PreparedScene& casters, uint64_t version, StaticMapCache& cache) {
    const std::vector<MeshInstance>& instances = casters.scene().instances;
    std::vector<Aabb> leaving;
    const bool first = cache.worldFromObject.size() != instances.size();
    if (!first && version == cache.geometryVersion) return leaving;
    if (first) cache.dynamic.assign(instances.size(), 0);
    for (size_t i = 0; i < instances.size(); ++i) {
        if (first || cache.dynamic[i] || instances[i].worldFromObject == cache.worldFromObject[i]) continue;
        cache.dynamic[i] = 1;
        leaving.push_back(cache.bounds[i]);
    }
    cache.worldFromObject.resize(instances.size());
    for (size_t i = 0; i < instances.size(); ++i) cache.worldFromObject[i] = instances[i].worldFromObject;
    cache.bounds = instanceBounds(casters.scene(), casters.world());
    cache.geometryVersion = version;
    if (first || !leaving.empty()) {
        cache.staticTriangles.clear(), cache.dynamicTriangles.clear();
        const std::vector<InstanceRange> ranges = instanceRanges(casters.scene());
        for (size_t i = 0; i < ranges.size(); ++i) {
            std::vector<uint32_t>& to = cache.dynamic[i] ? cache.dynamicTriangles : cache.staticTriangles;
            for (uint32_t t = 0; t < ranges[i].triangleCount; ++t) to.push_back(ranges[i].firstTriangle + t);
        }
    }
    return leaving;
}

// The square window of the map's viewport that holds `rect` (its side the rectangle's longer
// one, moved inside the map), drawn with `triangles` alone into cache.window; returns its
// corner, the map texel of the window's texel (0, 0).
glm::ivec2 drawWindow(const WorldGeometry& world, const std::vector<uint32_t>& triangles, const LightView& view,
                      DepthMapSettings settings, const MapRect& rect, raster::SimdLevel simd, StaticMapCache& cache) {
    const int mapSize = settings.size;
    const int side = std::max(rect.x1 - rect.x0, rect.y1 - rect.y0);
    const glm::ivec2 corner(std::min(rect.x0, mapSize - side), std::min(rect.y0, mapSize - side));
    settings.size = side;
    settings.window = {mapSize, mapSize, corner.x, corner.y};
    cache.window = renderDepthMap(world, triangles, view, settings, simd, std::move(cache.window),
                                  &cache.rasterizer.at(simd));
    return corner;
}

// Writes the window's texels over `rect` of `map`: replacing them, or keeping the nearer.
template <class Merge>
void mergeWindow(const DepthMap& window, glm::ivec2 corner, const MapRect& rect, Merge merge, DepthMap& map) {
    tbb::parallel_for(rect.y0, rect.y1, [&](int y) {
        for (int x = rect.x0; x < rect.x1; ++x) {
            float& texel = map.depth[raster::blockLinearIndex(x, y, map.tilesX)];
            texel = merge(texel, window.at(x - corner.x, y - corner.y));
        }
    });
}

// The static map drawn again where the leaving instances were (or whole, on a new view);
// returns the texels drawn, and where in stats.redrawn.
int64_t updateStaticMap(const PreparedScene& casters, const std::vector<Aabb>& leaving, const LightView& view,
                        const DepthMapSettings& settings, raster::SimdLevel simd, StaticMapCache& cache,
                        CachedMapStats& stats) {
    DepthMap& map = cache.staticMap;
    if (!cache.valid || map.size != settings.size || !sameView(map.view, view)) {
        if (cache.dynamicTriangles.empty())   // every triangle: the prepared scene's grouped draws
            map = renderDepthMap(casters, view, settings, simd, std::move(map), &cache.rasterizer.at(simd));
        else
            map = renderDepthMap(casters.world(), cache.staticTriangles, view, settings, simd, std::move(map),
                                 &cache.rasterizer.at(simd));
        cache.valid = true;
        stats.redrawn = {0, 0, map.size, map.size};
        return stats.redrawn.area();
    }
    int64_t drawn = 0;
    for (const Aabb& box : leaving) {
        const MapRect rect = texelsUnder(box, map);
        if (rect.empty()) continue;
        const glm::ivec2 corner = drawWindow(casters.world(), cache.staticTriangles, view, settings, rect, simd, cache);
        mergeWindow(cache.window, corner, rect, [](float, float drawnNow) { return drawnNow; }, map);
        drawn += rect.area();
        stats.redrawn = unite(stats.redrawn, rect);
    }
    return drawn;
}

// `out` = a copy of the static map (its depths copied in parallel into out's memory).
void copyStaticMap(const DepthMap& from, DepthMap& out) {
    out.size = from.size, out.tilesX = from.tilesX, out.view = from.view;
    out.texelFromWorld = from.texelFromWorld, out.worldFromTexel = from.worldFromTexel;
    out.depth.resize(from.depth.size());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, from.depth.size(), size_t(1) << 16), [&](const auto& r) {
        std::copy(from.depth.begin() + std::ptrdiff_t(r.begin()), from.depth.begin() + std::ptrdiff_t(r.end()),
                  out.depth.begin() + std::ptrdiff_t(r.begin()));
    });
}

}  // namespace

MapRect unite(const MapRect& a, const MapRect& b) {
    if (a.empty()) return b;
    if (b.empty()) return a;
    return {std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
}

MapRect texelsUnder(const Aabb& box, const DepthMap& map) {
    const MapRect whole{0, 0, map.size, map.size};
    glm::dvec2 lo(INFINITY), hi(-INFINITY);
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec3 P{corner & 1 ? box.max.x : box.min.x, corner & 2 ? box.max.y : box.min.y,
                           corner & 4 ? box.max.z : box.min.z};
        const glm::dvec4 t = map.texelFromWorld * glm::dvec4(P, 1.0);
        if (!(t.w > 0.0)) return whole;   // at or behind the apex plane: no bounded projection
        const glm::dvec2 texel = glm::dvec2(t) / t.w;
        lo = glm::min(lo, texel), hi = glm::max(hi, texel);
    }
    const auto clampTo = [&](double c) { return int(std::clamp(c, 0.0, double(map.size))); };
    const MapRect r{clampTo(std::floor(lo.x) - 1.0), clampTo(std::floor(lo.y) - 1.0), clampTo(std::ceil(hi.x) + 1.0),
                      clampTo(std::ceil(hi.y) + 1.0)};
    return r.empty() ? MapRect{} : r;
}

CachedMapStats drawCachedMap(const PreparedScene& casters, uint64_t geometryVersion, const LightView& view,
                             const DepthMapSettings& settings, raster::SimdLevel simd, StaticMapCache& cache,
                             DepthMap& out) {
    if (settings.layer == DepthLayer::Midpoint)
        throw std::invalid_argument("cache=static: the midpoint layer averages two layers, not a minimum to cache");
    CachedMapStats stats;
    const std::vector<Aabb> leaving = learnDynamic(casters, geometryVersion, cache);
    stats.redrawnTexels = updateStaticMap(casters, leaving, view, settings, simd, cache, stats);
    if (stats.redrawnTexels) stats.staticTriangles = cache.staticTriangles.size();
    if (cache.dynamicTriangles.empty()) return stats;   // the static map is the frame's
    copyStaticMap(cache.staticMap, out);
    MapRect moving;
    for (size_t i = 0; i < cache.dynamic.size(); ++i) {
        if (cache.dynamic[i]) moving = unite(moving, texelsUnder(cache.bounds[i], out)), ++stats.dynamicInstances;
    }
    if (moving.empty()) return stats;
    const glm::ivec2 corner = drawWindow(casters.world(), cache.dynamicTriangles, view, settings, moving, simd, cache);
    mergeWindow(cache.window, corner, moving, [](float kept, float drawn) { return std::min(kept, drawn); }, out);
    stats.dynamic = moving;
    stats.dynamicTexels = moving.area();
    stats.dynamicTriangles = cache.dynamicTriangles.size();
    return stats;
}

}  // namespace shadowlab
