// The `csm` technique: cascaded shadow maps for a directional light (Real-Time Rendering,
// 4th ed., section 7.4.1; cascades.h has the splits, bounds and texel snapping). Each
// cascade is an ordinary shadow map with the bias and filter settings of `shadow-map`;
// a receiver is looked up in the cascade of its slice only (no blending between them).
#include "shadows/maps/csm.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "shadows/debug_buffers.h"
#include "shadows/maps/shadow_map_debug.h"
#include "shadows/maps/shadow_map_settings.h"
#include "shadows/maps/shadow_map_techniques.h"

namespace shadowlab {
namespace {

CascadeSettings readCascadeSettings(const TechniqueParams& p, const ShadowMapSettings& s) {
    CascadeSettings c;
    c.count = p.integer("cascades", 1, 8);
    const std::string split = p.choice("split", {"log", "uniform", "practical"});
    c.scheme = split == "log" ? SplitScheme::Logarithmic : split == "uniform" ? SplitScheme::Uniform : SplitScheme::Practical;
    c.lambda = p.real("lambda", 0.0, 1.0);
    c.sampleBounds = p.choice("bounds", {"camera", "samples"}) == "samples";
    c.snap = p.flag("snap");
    c.resolution = s.resolution;
    c.marginTexels = kernelRadiusTexels(s.filter) + 1.5;   // the filter, plus half a texel of snapping
    return c;
}

void addStats(ShadowOutputs& out, const CascadedMaps& cm, int resolution, const ShadowLookup& lookup) {
    out.stats = {{"resolution", double(resolution)},
                 {"cascades", double(cm.cascades.size())},
                 {"texels_per_pixel_median", medianTexelDensity(lookup)}};
    for (size_t k = 0; k < cm.cascades.size(); ++k) {
        const Cascade& c = cm.cascades[k];
        const std::string name = "cascade" + std::to_string(k);
        out.stats.push_back({name + "_split_near", c.nearDistance});
        out.stats.push_back({name + "_split_far", c.farDistance});
        if (!c.hasReceivers) continue;
        out.stats.push_back({name + "_light_near", c.view.zNear});
        out.stats.push_back({name + "_light_far", c.view.zFar});
    }
}

ShadowOutputs runCsm(const ShadowInputs& in) {
    const ShadowMapSettings s = readShadowMapSettings(in.params);
    const CascadeSettings cs = readCascadeSettings(in.params, s);
    if (in.light.type != LightType::Directional) throw std::invalid_argument("csm: needs a directional light");
    ShadowOutputs out;
    if (std::find(in.gbuffer.hit.begin(), in.gbuffer.hit.end(), 1) == in.gbuffer.hit.end()) {
        out.visibility.assign(in.gbuffer.pixelCount(), 0.0f);
        return out;
    }
    const CascadedMaps cm = renderCascades(in.light, in.scene().camera, in.gbuffer, in.world(), cs, depthMapSettings(s), in.simd);
    const ShadowLookup lookup = lookUpShadows(in.gbuffer, in.scene().camera, in.light, cm.maps,
                                              cascadeSelector(cm, in.scene().camera), s.bias, makePcfKernel(s.filter),
                                              !in.debugDir.empty());
    addStats(out, cm, s.resolution, lookup);
    const DebugBuffers debug(in.debugDir, "csm");
    for (size_t k = 0; k < cm.maps.size(); ++k) {
        if (cm.maps[k].size) writeDepthMap(debug, "depth-cascade" + std::to_string(k), cm.maps[k]);
    }
    if (debug.enabled()) writeTexelDensity(debug, in.gbuffer, lookup);
    writeMapColouring(in.debugDir, "csm", "cascades", in.gbuffer, lookup);
    out.visibility = lookup.visibility;
    return out;
}

}  // namespace

CascadedMaps renderCascades(const Light& sun, const Camera& camera, const GBuffer& receivers, const WorldGeometry& world,
                            const CascadeSettings& cascades, const DepthMapSettings& maps, raster::SimdLevel simd) {
    CascadedMaps out;
    out.cascades = fitCascades(sun, camera, receivers, world, cascades);
    out.maps.resize(out.cascades.size());
    for (size_t k = 0; k < out.cascades.size(); ++k) {
        if (out.cascades[k].hasReceivers) out.maps[k] = renderDepthMap(world, out.cascades[k].view, maps, simd);
    }
    return out;
}

MapSelector cascadeSelector(const CascadedMaps& cm, const Camera& camera) {
    return [&cm, camera](const glm::dvec3& P, size_t) {
        const int k = cascadeOf(cm.cascades, viewDepth(camera, P));
        return cm.maps[k].size ? k : -1;
    };
}

Technique cascadedShadowMapTechnique() {
    std::vector<ParamSpec> params = shadowMapParamSpecs();
    params.push_back({"cascades", "4", "number of cascades (1..8)"});
    params.push_back({"split", "practical", "log (RTR eq. 7.5) | uniform | practical (lambda log + (1 - lambda) uniform)"});
    params.push_back({"lambda", "0.75", "practical split: weight of the logarithmic split"});
    params.push_back({"bounds", "samples", "split range: camera (near/far planes) | samples (nearest/farthest receiver, SDSM)"});
    params.push_back({"snap", "on", "snap each cascade to whole texels so shadows do not shimmer (on | off)"});
    return {"csm", "cascaded shadow maps (RTR 7.4.1) for directional lights: split schemes, SDSM bounds, texel snapping",
            params, runCsm};
}

}  // namespace shadowlab
