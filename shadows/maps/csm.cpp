// The `csm` technique: cascaded shadow maps for a directional light (Real-Time Rendering,
// 4th ed., section 7.4.1; cascades.h has the splits, bounds and texel snapping). Each
// cascade is an ordinary shadow map with the bias and filter settings of `shadow-map`;
// a receiver is looked up in the cascade of its slice only (no blending between them).
// Cascades split the camera's view for a light as far away as the sun. Any other light's
// frustum is already fitted to the receivers, so, as engines do, it gets the plain shadow map
// (one frustum or cube faces) with csm's map settings: a scene's every light in one frame.
// With update-every=k the far cascades are drawn every k-th frame, staggered (stepped
// updates, csm.h: cascadeDue), and kept with the view they were drawn with in between.
#include "shadows/maps/csm.h"

#include <algorithm>
#include <string>
#include <utility>

#include "shadows/debug_buffers.h"
#include "shadows/maps/shadow_map_debug.h"
#include "shadows/maps/shadow_map_settings.h"
#include "shadows/maps/shadow_map_techniques.h"
#include "shadows/maps/static_map_cache.h"
#include "shadows/stage_timer.h"

namespace shadowlab {
namespace {

struct CsmSettings {
    ShadowMapSettings map;
    CascadeSettings cascades;   // its resolution and margin follow from the map's (read())
    int updateEvery = 1;        // stepped updates: far cascades drawn every k-th frame (csm.h)
    bool redrawMoved = true;    // ... and a stale cascade a moved caster touches drawn anyway
};

const SettingsTable<CsmSettings>& csmSettingsTable() {
    using S = CsmSettings;
    static const auto table =
        SettingsTable<S>()
            .include(member(&S::map), shadowMapSettingsTable())
            .integer("cascades", member(&S::cascades, &CascadeSettings::count), 1, 8, "number of cascades")
            .choice("split", member(&S::cascades, &CascadeSettings::scheme),
                    {{"log", SplitScheme::Logarithmic, "RTR eq. 7.5"},
                     {"uniform", SplitScheme::Uniform},
                     {"practical", SplitScheme::Practical, "lambda log + (1 - lambda) uniform"}})
            .real("lambda", member(&S::cascades, &CascadeSettings::lambda), 0.0, 1.0,
                  "practical split: weight of the logarithmic split")
            .choice("bounds", member(&S::cascades, &CascadeSettings::sampleBounds),
                    {{"camera", false, "near/far planes"}, {"samples", true, "nearest/farthest receiver, SDSM"}},
                    "split range")
            .flag("snap", member(&S::cascades, &CascadeSettings::snap),
                  "snap each cascade to whole texels so shadows do not shimmer")
            .integer("update-every", member(&S::updateEvery), 1, 16,
                     "stepped updates: cascade 0 every frame, the others every k-th frame, staggered")
            .choice("moved-casters", member(&S::redrawMoved),
                    {{"redraw", true, "a stale cascade a moved caster's bounds touch is drawn anyway"},
                     {"keep", false, "stale cascades keep moved casters where they were"}},
                    "update-every > 1");
    return table;
}

CsmSettings readCsmSettings(const TechniqueParams& params) {
    CsmSettings s = csmSettingsTable().read(params);
    s.cascades.resolution = s.map.resolution;
    s.cascades.marginTexels = kernelRadiusTexels(s.map.filter) + 1.5;   // the filter, plus half a texel of snapping
    return s;
}

void addStats(ShadowOutputs& out, const CascadedMaps& cm, int resolution, const ShadowLookup& lookup) {
    out.stats = {{"resolution_texels", double(resolution)},
                 {"cascades_count", double(cm.cascades.size())},
                 {"median_texels_per_pixel", medianTexelDensity(lookup)}};
    for (size_t k = 0; k < cm.cascades.size(); ++k) {
        const Cascade& c = cm.cascades[k];
        const std::string name = "cascade" + std::to_string(k);
        out.stats.push_back({name + "_split_near_m", c.nearDistance});
        out.stats.push_back({name + "_split_far_m", c.farDistance});
        if (!c.hasReceivers) continue;
        out.stats.push_back({name + "_light_near_m", c.view.zNear});
        out.stats.push_back({name + "_light_far_m", c.view.zFar});
    }
    int stale = 0;
    for (size_t k = 0; k < cm.maps.size(); ++k) stale += cm.maps[k].size && !cm.drawnNow[k];
    out.stats.push_back({"cache_stale_cascades_count", double(stale)});
}

// A local or area light (its centre): `shadow-map`'s frame with these map settings, its
// stats and debug buffers, and no cascades.
ShadowOutputs localLightShadows(const ShadowInputs& in, const ShadowMapSettings& map) {
    ShadowOutputs out = runShadowMap(in, ShadowMapTechniqueSettings{.map = map});
    out.stats.insert(out.stats.begin(), {"cascades_count", 0.0});
    return out;
}

ShadowOutputs runCsm(const ShadowInputs& in) {
    const CsmSettings settings = readCsmSettings(in.params);
    const ShadowMapSettings& s = settings.map;
    const CascadeSettings& cs = settings.cascades;
    if (in.light.type != LightType::Directional) return localLightShadows(in, s);
    if (!anyReachable(in.gbuffer, in.light)) return unlitOutputs(in.gbuffer);   // settings checked first
    ShadowOutputs out;
    StageTimer timer;
    CascadedMaps& cm = in.kept().state<CascadedMaps>();   // last frame's, whose memory the maps reuse
    const std::vector<Aabb> moved = settings.updateEvery > 1 && settings.redrawMoved
                                        ? movedCasters(in.casters(), in.prepared.geometryVersion(), cm)
                                        : std::vector<Aabb>{};
    cm = renderCascades(in.light, in.camera(), in.gbuffer, in.casterWorld(), cs, depthMapSettings(s), in.simd, std::move(cm),
                        settings.updateEvery, moved);
    timer.lap("cascades");
    ShadowLookup lookup = lookUpShadows(in.gbuffer, in.camera(), in.light, cm.maps,
                                        CascadeSelector{cm, in.camera()}, s.bias, makePcfKernel(s.filter, in.frameIndex), in.simd,
                                        !in.debugDir.empty());
    timer.lap("lookup");
    addStats(out, cm, s.resolution, lookup);
    timer.appendTo(out.stats);
    const DebugBuffers debug(in.debugDir, "csm");
    for (size_t k = 0; k < cm.maps.size(); ++k) {
        if (cm.maps[k].size) writeDepthMap(debug, "depth-cascade" + std::to_string(k), cm.maps[k]);
    }
    if (debug.enabled()) writeTexelDensity(debug, in.gbuffer, lookup);
    writeMapColouring(in.debugDir, "csm", "cascades", in.gbuffer, lookup);
    out.visibility = std::move(lookup.visibility);   // the last use
    return out;
}

}  // namespace

bool cascadeDue(const CascadedMaps& kept, size_t cascade, int updateEvery, std::span<const Aabb> moved) {
    if (cascade == 0 || (kept.frame + cascade) % uint64_t(updateEvery) == 0) return true;
    return std::any_of(moved.begin(), moved.end(),
                       [&](const Aabb& box) { return !texelsUnder(box, kept.maps[cascade]).empty(); });
}

std::vector<Aabb> movedCasters(const PreparedScene& casters, uint64_t geometryVersion, CascadedMaps& kept) {
    std::vector<Aabb> moved;
    if (!kept.casterBoxes.empty() && kept.geometryVersion == geometryVersion) return moved;
    std::vector<Aabb> boxes = instanceBounds(casters.scene(), casters.world());
    for (size_t i = 0; i < boxes.size() && boxes.size() == kept.casterBoxes.size(); ++i) {
        const Aabb &was = kept.casterBoxes[i], &is = boxes[i];
        if (was.min != is.min || was.max != is.max) moved.push_back(was), moved.push_back(is);
    }
    kept.casterBoxes = std::move(boxes), kept.geometryVersion = geometryVersion;
    return moved;
}

CascadedMaps renderCascades(const Light& sun, const Camera& camera, const GBuffer& receivers, const WorldGeometry& world,
                            const CascadeSettings& cascades, const DepthMapSettings& maps, raster::SimdLevel simd,
                            CascadedMaps memory, int updateEvery, std::span<const Aabb> moved) {
    CascadedMaps out = std::move(memory);
    const glm::dvec3 towardsLight = glm::normalize(glm::dvec3(sun.direction));
    // What the kept maps cannot serve: no frame before, another sun, another cascade count.
    const bool all = out.frame == 0 || towardsLight != out.towardsLight || out.maps.size() != size_t(cascades.count);
    if (all) out.frame = 0;
    out.cascades = fitCascades(sun, camera, receivers, world, cascades, simd);
    out.maps.resize(out.cascades.size());
    out.drawnNow.assign(out.cascades.size(), 0);
    for (size_t k = 0; k < out.cascades.size(); ++k) {
        DepthMap& map = out.maps[k];
        if (!out.cascades[k].hasReceivers) {
            map.size = 0;   // not drawn; its memory kept for a later frame
        } else if (all || map.size != maps.size || cascadeDue(out, k, updateEvery, moved)) {
            map = renderDepthMap(world, out.cascades[k].view, maps, simd, std::move(map), &out.rasterizer.at(simd));
            out.drawnNow[k] = 1;
        }
    }
    out.towardsLight = towardsLight;
    ++out.frame;
    return out;
}

Technique cascadedShadowMapTechnique() {
    return {.name = "csm",
            .description = "cascaded shadow maps (RTR 7.4.1) for directional lights: split schemes, SDSM "
                           "bounds, texel snapping; other lights get shadow-map's frame",
            .params = csmSettingsTable().specs(),
            .run = runCsm,
            .referenceName = "reference",
            .output = TechniqueOutput::Visibility};
}

}  // namespace shadowlab
