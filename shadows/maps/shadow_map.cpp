// The `shadow-map` technique (Williams 1978; Real-Time Rendering, 4th ed., section 7.4):
// render the depths the light sees, then compare every camera pixel's surface point with
// them (shadow_lookup.h), with the bias of shadow_bias.h and the filter of pcf.h.
//
// The light's view is fitted to the visible receivers (light_view.h, RTR Figure 7.11):
// orthographic for a directional light (optionally warped by LiSPSM, lispsm.h),
// perspective for a spot or point light, and six cube faces (RTR 7.4, "omnidirectional
// shadow maps") for a point light whose receivers surround it, or on request. A receiver
// uses the face whose 90-degree pyramid holds it, the same test fitCubeFace fits with;
// filter taps beyond a face's border read its border texels (no cross-face filtering).
// A face no visible receiver lies in is not drawn (docs/many-lights.md, cube-face
// culling); maps_count counts the faces drawn.
//
// With cache=static one frustum's map is kept across frames for the casters that never
// moved, and each frame draws only the moving ones over a copy of it (static_map_cache.h,
// docs/cached-shadow-maps.md): the same bits as drawing it whole. A view fitted to the
// visible receivers changes as the camera moves, and every change redraws the whole static
// map; fit=scene fits the view to the world's box instead, which stays.
#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <stdexcept>
#include <utility>

#include "shadows/debug_buffers.h"
#include "shadows/depth_map.h"
#include "shadows/kept_raster.h"
#include "shadows/light_view.h"
#include "shadows/maps/lispsm.h"
#include "shadows/maps/shadow_lookup.h"
#include "shadows/maps/shadow_map_debug.h"
#include "shadows/maps/shadow_map_settings.h"
#include "shadows/maps/shadow_map_techniques.h"
#include "shadows/maps/static_map_cache.h"
#include "shadows/stage_timer.h"

namespace shadowlab {
namespace {

bool insideFace(const DepthMap& face, const glm::dvec3& P) { return face.size != 0 && insideCubeFace(face.view, P); }

// A frame's maps. The technique keeps them between frames (technique_history.h) and draws
// each frame's into the last one's memory with the same rasterizer (kept_raster.h), so a
// steady state allocates no map.
struct LightMaps {
    std::vector<DepthMap> maps;     // one map, or six cube faces (size 0 where a face has no receiver)
    bool cube = false;
    double nOpt = 0.0;              // LiSPSM's n, infinity when it kept the uniform map
    bool cached = false;            // maps[0] came from the static map's cache (cacheStats)
    CachedMapStats cacheStats;
    KeptRasterizer rasterizer;
};

void drawCubeMaps(const ShadowInputs& in, const Light& light, const ShadowMapSettings& s, const LightFitOptions& o,
                  StageTimer& timer, LightMaps& out) {
    out.cube = true;
    out.maps.resize(6);
    for (int face = 0; face < 6; ++face) {
        LightView view;
        const bool used = fitCubeFace(light, face, in.gbuffer, in.casterWorld(), o, view);
        timer.lap("light_view");
        DepthMap& map = out.maps[face];
        if (used) {
            map = renderDepthMap(in.casters(), view, depthMapSettings(s), in.simd, std::move(map),
                                 &out.rasterizer.at(in.simd));
        } else {
            map.size = 0;   // not drawn; its memory kept for a later frame
        }
        timer.lap("depth_map");
    }
}

// Stages light_view (fitting the frustum) and depth_map (drawing it), into `out`, the maps
// of the frame before.
void drawLightMaps(const ShadowInputs& in, const Light& light, const ShadowMapTechniqueSettings& settings,
                   StageTimer& timer, LightMaps& out) {
    const ShadowMapSettings& s = settings.map;
    LightFitOptions options;
    options.cullCubeFaces = settings.cullCubeFaces;
    options.resolution = s.resolution;
    options.marginTexels = kernelRadiusTexels(s.filter) + 1.5;
    options.simd = in.simd;
    options.scratch = &in.kept().state<LightViewScratch>();
    out.nOpt = 0.0, out.cached = false;
    if (settings.alwaysCube) return drawCubeMaps(in, light, s, options, timer, out);
    LightView view;
    try {
        view = settings.fitWorld ? fitLightViewToWorld(light, in.casterWorld(), options)
                                 : fitLightView(light, in.gbuffer, in.casterWorld(), options);
    } catch (const std::invalid_argument&) {
        if (light.type != LightType::Point) throw;
        if (settings.cacheStatic) throw std::invalid_argument("shadow-map: cache=static keeps one frustum's map; this "
                                                              "point light needs cube faces");
        return drawCubeMaps(in, light, s, options, timer, out);   // receivers all around the light
    }
    if (settings.lispsm) {
        const LispsmView warped = lispsmView(view, light, in.camera(), in.gbuffer, s.resolution, options.marginTexels);
        view = warped.view, out.nOpt = warped.nOpt;
    }
    timer.lap("light_view");
    out.cube = false;
    out.maps.resize(1);
    if (settings.cacheStatic) {
        out.cached = true;
        out.cacheStats = drawCachedMap(in.casters(), in.prepared.geometryVersion(), view, depthMapSettings(s), in.simd,
                                       in.kept().state<StaticMapCache>(), out.maps[0]);
    } else {
        out.maps[0] = renderDepthMap(in.casters(), view, depthMapSettings(s), in.simd, std::move(out.maps[0]),
                                     &out.rasterizer.at(in.simd));
    }
    timer.lap("depth_map");
}

// The map selector of cube maps: the first face whose pyramid holds P.
struct CubeFace {
    const std::vector<DepthMap>& faces;
    int operator()(const glm::dvec3& P) const {
        for (int face = 0; face < 6; ++face) {
            if (insideFace(faces[face], P)) return face;
        }
        return -1;
    }
};

// The frame's maps: lm.maps, or with cache=static the cache's frame map (the static map
// itself while no caster moves).
std::span<const DepthMap> frameMaps(const ShadowInputs& in, const LightMaps& lm) {
    if (!lm.cached) return lm.maps;
    return {&cachedFrameMap(in.kept().state<StaticMapCache>(), lm.maps[0]), 1};
}

ShadowLookup lookUp(const ShadowInputs& in, const Light& light, const LightMaps& lm, const ShadowMapSettings& s) {
    const PcfKernel kernel = makePcfKernel(s.filter, in.frameIndex);
    const Camera& camera = in.camera();
    const bool everyPixelDensity = !in.debugDir.empty();
    if (lm.cube) return lookUpShadows(in.gbuffer, camera, light, lm.maps, CubeFace{lm.maps}, s.bias, kernel, in.simd,
                                         everyPixelDensity);
    return lookUpShadows(in.gbuffer, camera, light, frameMaps(in, lm), OneMap{}, s.bias, kernel, in.simd,
                         everyPixelDensity);
}

void addStats(ShadowOutputs& out, std::span<const DepthMap> maps, const LightMaps& lm, const ShadowMapSettings& s,
              const ShadowLookup& lookup) {
    double zNear = std::numeric_limits<double>::infinity(), zFar = 0.0;
    int drawn = 0;
    for (const DepthMap& m : maps) {
        if (m.size == 0) continue;
        ++drawn, zNear = std::min(zNear, m.view.zNear), zFar = std::max(zFar, m.view.zFar);
    }
    out.stats = {{"resolution_texels", double(s.resolution)},
                 {"maps_count", double(drawn)},
                 {"median_texels_per_pixel", medianTexelDensity(lookup)},
                 {"light_near_m", zNear},
                 {"light_far_m", zFar}};
    if (lm.nOpt != 0.0) out.stats.push_back({"lispsm_n_opt_m", lm.nOpt});
    if (!lm.cached) return;
    const CachedMapStats& c = lm.cacheStats;
    const double texels = double(s.resolution) * double(s.resolution);
    out.stats.push_back({"cache_redrawn_texels_percent", 100.0 * double(c.redrawnTexels) / texels});
    out.stats.push_back({"cache_dynamic_texels_percent", 100.0 * double(c.dynamicTexels) / texels});
    out.stats.push_back({"cache_static_triangles", double(c.staticTriangles)});
    out.stats.push_back({"cache_dynamic_triangles", double(c.dynamicTriangles)});
    out.stats.push_back({"cache_dynamic_instances_count", double(c.dynamicInstances)});
}

// cache=static's buffers: the static casters' map as kept, and the texels this frame drew
// (1 where the static map was drawn again, 0.5 where the dynamic casters were drawn over it).
void writeCacheDebug(const DebugBuffers& debug, const StaticMapCache& cache, const CachedMapStats& stats) {
    writeDepthMap(debug, "static-depth", cache.staticMap);
    const int n = cache.staticMap.size;
    std::vector<float> drawn(size_t(n) * size_t(n), 0.0f);
    for (const auto& [rect, value] : {std::pair{stats.dynamic, 0.5f}, std::pair{stats.redrawn, 1.0f}}) {
        for (int y = rect.y0; y < rect.y1; ++y) {
            std::fill(drawn.begin() + std::ptrdiff_t(size_t(y) * size_t(n) + size_t(rect.x0)),
                      drawn.begin() + std::ptrdiff_t(size_t(y) * size_t(n) + size_t(rect.x1)), value);
        }
    }
    debug.write("cache-drawn", n, n, drawn, 0.0f, 1.0f);
}

void writeDebug(const ShadowInputs& in, const LightMaps& lm, const ShadowMapSettings& s, const ShadowLookup& lookup) {
    const DebugBuffers debug(in.debugDir, "shadow-map");
    if (!debug.enabled()) return;
    if (lm.cached) writeCacheDebug(debug, in.kept().state<StaticMapCache>(), lm.cacheStats);
    const std::span<const DepthMap> maps = frameMaps(in, lm);
    for (size_t k = 0; k < maps.size(); ++k) {
        if (maps[k].size == 0) continue;
        const std::string suffix = lm.cube ? std::string("-face-") + kCubeFaceNames[k] : "";
        writeDepthMap(debug, "depth" + suffix, maps[k]);
        if (s.layer == DepthLayer::Midpoint) {
            // The two layers the midpoint averages, drawn again only for this picture.
            for (DepthLayer layer : {DepthLayer::First, DepthLayer::Second}) {
                DepthMapSettings one = depthMapSettings(s);
                one.layer = layer;
                writeDepthMap(debug, (layer == DepthLayer::First ? "depth-first" : "depth-second") + suffix,
                              renderDepthMap(in.casters(), maps[k].view, one, in.simd));
            }
        }
    }
    writeTexelDensity(debug, in.gbuffer, lookup);
    if (lm.cube) writeMapColouring(in.debugDir, "shadow-map", "faces", in.gbuffer, lookup);
}

}  // namespace

const SettingsTable<ShadowMapTechniqueSettings>& shadowMapTechniqueSettingsTable() {
    using S = ShadowMapTechniqueSettings;
    static const auto table =
        SettingsTable<S>()
            .include(member(&S::map), shadowMapSettingsTable())
            .choice("cube", member(&S::alwaysCube),
                    {{"auto", false, "six faces when one frustum cannot hold the receivers"}, {"always", true}},
                    "point lights")
            .choice("cube-faces", member(&S::cullCubeFaces),
                    {{"visible", true, "only the faces whose pyramid holds a visible receiver"},
                     {"all", false, "all six (to measure the culling; the same V)"}},
                    "point lights")
            .choice("warp", member(&S::lispsm),
                    {{"none", false}, {"lispsm", true, "light space perspective shadow map"}}, "directional lights")
            .choice("fit", member(&S::fitWorld),
                    {{"receivers", false, "the visible receivers: follows the camera"},
                     {"scene", true, "every vertex and the world's box: stays while the camera moves"}},
                    "one frustum's view")
            .choice("cache", member(&S::cacheStatic),
                    {{"off", false},
                     {"static", true, "keep the static casters' map across frames, draw the moving ones over a copy"}},
                    "one frustum; not layer=midpoint");
    return table;
}

ShadowOutputs runShadowMap(const ShadowInputs& in, const ShadowMapTechniqueSettings& settings) {
    const ShadowMapSettings& s = settings.map;
    const bool forceCube = settings.alwaysCube;
    const bool lispsm = settings.lispsm;
    if (settings.cacheStatic && forceCube)
        throw std::invalid_argument("shadow-map: cache=static keeps one frustum's map, not cube faces");
    if (settings.cacheStatic && s.layer == DepthLayer::Midpoint)
        throw std::invalid_argument("shadow-map: cache=static needs layer=first or second (the midpoint is no minimum)");
    const Light light = pointLightFor(in.light);
    if (lispsm && light.type != LightType::Directional) {
        throw std::invalid_argument("shadow-map: warp=lispsm needs a directional light");
    }
    if (forceCube && light.type != LightType::Point) throw std::invalid_argument("shadow-map: cube=always needs a point light");
    if (!anyReachable(in.gbuffer, in.light)) return unlitOutputs(in.gbuffer);   // settings checked first
    ShadowOutputs out;
    StageTimer timer;
    LightMaps& lm = in.kept().state<LightMaps>();
    drawLightMaps(in, light, settings, timer, lm);
    ShadowLookup lookup = lookUp(in, light, lm, s);
    timer.lap("lookup");
    addStats(out, frameMaps(in, lm), lm, s, lookup);
    timer.appendTo(out.stats);
    writeDebug(in, lm, s, lookup);
    out.visibility = std::move(lookup.visibility);   // the last use
    return out;
}

Technique shadowMapTechnique() {
    return {.name = "shadow-map",
            .description = "shadow map (RTR 7.4): fitted light frustum, cube faces for surrounded point "
                           "lights, bias modes, PCF filters, LiSPSM",
            .params = shadowMapTechniqueSettingsTable().specs(),
            .run = [](const ShadowInputs& in) {
                return runShadowMap(in, shadowMapTechniqueSettingsTable().read(in.params));
            },
            .referenceName = "reference",
            .output = TechniqueOutput::Visibility};
}

}  // namespace shadowlab
