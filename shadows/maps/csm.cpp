// The `csm` technique: cascaded shadow maps for a directional light (Real-Time Rendering,
// 4th ed., section 7.4.1; cascades.h has the splits, bounds and texel snapping). Each
// cascade is an ordinary shadow map with the bias and filter settings of `shadow-map`;
// a receiver is looked up in the cascade of its slice only (no blending between them).
#include "shadows/maps/csm.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

#include "shadows/debug_buffers.h"
#include "shadows/maps/shadow_map_debug.h"
#include "shadows/maps/shadow_map_settings.h"
#include "shadows/maps/shadow_map_techniques.h"
#include "shadows/stage_timer.h"

namespace shadowlab {
namespace {

CascadeSettings readCascadeSettings(const TechniqueParams& p, const ShadowMapSettings& s) {
    CascadeSettings c;
    c.count = p.integer("cascades");
    c.scheme = p.choice<SplitScheme>("split");
    c.lambda = p.real("lambda");
    c.sampleBounds = p.choice<bool>("bounds");
    c.snap = p.flag("snap");
    c.resolution = s.resolution;
    c.marginTexels = kernelRadiusTexels(s.filter) + 1.5;   // the filter, plus half a texel of snapping
    return c;
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
}

ShadowOutputs runCsm(const ShadowInputs& in) {
    const ShadowMapSettings s = readShadowMapSettings(in.params);
    const CascadeSettings cs = readCascadeSettings(in.params, s);
    if (in.light.type != LightType::Directional) throw std::invalid_argument("csm: needs a directional light");
    if (!anySurface(in.gbuffer)) return unlitOutputs(in.gbuffer);   // settings checked first
    ShadowOutputs out;
    StageTimer timer;
    const CascadedMaps cm = renderCascades(in.light, in.camera(), in.gbuffer, in.casterWorld(), cs, depthMapSettings(s), in.simd);
    timer.lap("cascades");
    ShadowLookup lookup = lookUpShadows(in.gbuffer, in.camera(), in.light, cm.maps,
                                        CascadeSelector{cm, in.camera()}, s.bias, makePcfKernel(s.filter), in.simd,
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

CascadedMaps renderCascades(const Light& sun, const Camera& camera, const GBuffer& receivers, const WorldGeometry& world,
                            const CascadeSettings& cascades, const DepthMapSettings& maps, raster::SimdLevel simd) {
    CascadedMaps out;
    out.cascades = fitCascades(sun, camera, receivers, world, cascades, simd);
    out.maps.resize(out.cascades.size());
    for (size_t k = 0; k < out.cascades.size(); ++k) {
        if (out.cascades[k].hasReceivers) out.maps[k] = renderDepthMap(world, out.cascades[k].view, maps, simd);
    }
    return out;
}

Technique cascadedShadowMapTechnique() {
    std::vector<ParamSpec> params = shadowMapParamSpecs();
    params.push_back(integerParam("cascades", 4, 1, 8, "number of cascades"));
    params.push_back(choiceParam<SplitScheme>("split", "practical",
                                              {{"log", SplitScheme::Logarithmic, "RTR eq. 7.5"},
                                               {"uniform", SplitScheme::Uniform},
                                               {"practical", SplitScheme::Practical, "lambda log + (1 - lambda) uniform"}}));
    params.push_back(realParam("lambda", 0.75, 0.0, 1.0, "practical split: weight of the logarithmic split"));
    params.push_back(choiceParam<bool>("bounds", "samples",
                                       {{"camera", false, "near/far planes"},
                                        {"samples", true, "nearest/farthest receiver, SDSM"}},
                                       "split range"));
    params.push_back(flagParam("snap", true, "snap each cascade to whole texels so shadows do not shimmer"));
    return {.name = "csm",
            .description = "cascaded shadow maps (RTR 7.4.1) for directional lights: split schemes, SDSM "
                           "bounds, texel snapping",
            .params = params,
            .run = runCsm,
            .referenceName = "reference",
            .output = TechniqueOutput::Visibility};
}

}  // namespace shadowlab
