// Shadow fins for a disk light (Cai, Jia, Wang, Hu and Martin 2006, "Rendering Soft
// Shadows using Multi-layered Shadow Fins"), and the two older methods it compares itself
// with (its sections 2 and 7.1), all as one mechanism with different fins:
//
//   technique       fins            edge weight  fin width                   layers
//   fins            inner + outer   0.5 (eq. 1)  light radius R (eq. 3)      param (16)
//   penumbra-maps   outer           1            light radius R (eq. 3)      1
//   smoothies       outer           1            angular width t_s (param)   1
//
// Outer-only methods put the whole penumbra outside the hard shadow, so they over-estimate
// the umbra; smoothies also ignore the light's size (Cai et al., section 7.1).
//
// Per frame:
//   1. the light's view from the disk's centre along its normal, fitted to the receivers
//      (light_view.h); its far plane is the reference receiver plane L_0 (section 3.1);
//   2. silhouette edges w.r.t. the centre (silhouette.h), fins (fin_geometry.h);
//   3. layers of about equal numbers of edges (fin_layers.h, section 4.1), each object
//      with its fins in the layer of its edges' median midpoint;
//   4. per layer, near to far: the hard shadow map of the layer's objects, the inner and
//      outer penumbra maps of their fins (penumbra_maps.h), and the illuminance buffer
//      updated from them (illuminance_buffer.h, sections 3.4 and 4.2).
// V is the illuminance buffer; the final image multiplies it into the shading (section 4.3).
#include "shadows/fins/fins.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "scenes/edge_adjacency.h"
#include "shadows/fins/fin_geometry.h"
#include "shadows/fins/fin_layers.h"
#include "shadows/fins/fins_debug.h"
#include "shadows/fins/illuminance_buffer.h"
#include "shadows/fins/fin_maps.h"
#include "shadows/silhouettes/silhouette.h"
#include "shadows/volumes/volume_extrusion.h"

namespace shadowlab {
namespace {

// The `layers` parameter's upper bound: the paper uses 16 and finds no scene needing more
// (section 6); past 64 a layer would hold a handful of edges even on the bunny.
constexpr int kMaxLayers = 64;

struct FinSettings {
    std::string technique;
    FinStyle style;
    int layers = 1;
    int resolution = 1024;
    Falloff falloff = Falloff::Linear;
    BiasSettings bias;   // slope-scaled, as the shadow-map default (shadow_bias.h)
};

double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// What each layer draws: its objects' triangles into the hard shadow map, their fins into
// the penumbra maps (fin_layers.h: objects go whole into one layer).
struct LayerContents {
    std::vector<glm::uvec3> geometry, innerFins, outerFins;
    bool empty() const { return geometry.empty() && innerFins.empty() && outerFins.empty(); }
};

struct Layering {
    LightLayers layers;
    std::vector<int> instanceLayer;
    std::vector<LayerContents> contents;
};

uint32_t instanceOfVertex(const std::vector<InstanceRange>& ranges, uint32_t vertex) {
    const auto after = std::upper_bound(ranges.begin(), ranges.end(), vertex,
                                        [](uint32_t v, const InstanceRange& r) { return v < r.firstVertex; });
    return uint32_t(after - ranges.begin() - 1);
}

Layering layerScene(const ShadowInputs& in, const Fins& fins, const LightPlane& light, const LightView& view,
                    int layerCount) {
    const std::vector<InstanceRange> ranges = instanceRanges(in.scene);
    std::vector<uint32_t> edgeInstance;
    for (const SilhouetteEdge& e : fins.edges) edgeInstance.push_back(instanceOfVertex(ranges, e.from));
    std::vector<double> fallback;   // instances without silhouette edges: their first vertex
    for (const InstanceRange& r : ranges) fallback.push_back(light.distance(glm::dvec3(in.world.positions[r.firstVertex])));
    Layering l{LightLayers(fins.midpointDistance, view.zNear, view.zFar, layerCount), {}, {}};
    l.instanceLayer = instanceLayers(l.layers, fins.midpointDistance, edgeInstance, fallback);
    l.contents.resize(l.layers.count());
    for (size_t i = 0; i < ranges.size(); ++i) {
        const auto first = in.world.triangles.begin() + ranges[i].firstTriangle;
        std::vector<glm::uvec3>& geometry = l.contents[l.instanceLayer[i]].geometry;
        geometry.insert(geometry.end(), first, first + ranges[i].triangleCount);
    }
    auto distribute = [&](const FinPrimitives& kind, std::vector<glm::uvec3> LayerContents::*list) {
        for (size_t t = 0; t < kind.triangles.size(); ++t) {
            (l.contents[l.instanceLayer[edgeInstance[kind.owner[t]]]].*list).push_back(kind.triangles[t]);
        }
    };
    distribute(fins.inner, &LayerContents::innerFins);
    distribute(fins.outer, &LayerContents::outerFins);
    return l;
}

// 1 where a surface faces the light's centre (the reference's dot(N, L - P) > 0), else 0.
std::vector<uint8_t> facingLight(const GBuffer& g, const LightPlane& light) {
    std::vector<uint8_t> facing(g.pixelCount(), 0);
    for (size_t k = 0; k < g.pixelCount(); ++k) {
        facing[k] = g.hit[k] && glm::dot(glm::dvec3(g.normal[k]), light.centre - glm::dvec3(g.position[k])) > 0.0;
    }
    return facing;
}

ShadowOutputs renderFinShadows(const ShadowInputs& in, const LightPlane& light, const FinSettings& s) {
    ShadowOutputs out;
    if (std::find(in.gbuffer.hit.begin(), in.gbuffer.hit.end(), 1) == in.gbuffer.hit.end()) {
        out.visibility.assign(in.gbuffer.pixelCount(), 0.0f);
        return out;
    }
    auto start = std::chrono::steady_clock::now();
    LightFitOptions fit;
    fit.resolution = s.resolution;
    fit.axis = light.normal;
    const LightView view = fitLightView(pointLightFor(in.light), in.gbuffer, in.world, fit);
    const double L0 = view.zFar;   // the reference receiver plane (section 3.1)
    const std::vector<SilhouetteEdge> silhouette =
        sceneSilhouette(in.scene, in.world, *cachedSceneEdgeAdjacency(in.scene), glm::dvec4(light.centre, 1.0));
    const Fins fins = buildFins(in.world.positions, silhouette, light, L0, s.style);
    const Layering layering = layerScene(in, fins, light, view, s.layers);
    const double finsMs = millisecondsSince(start);

    start = std::chrono::steady_clock::now();
    IlluminanceBuffer buffer(in.gbuffer, facingLight(in.gbuffer, light));
    const IlluminanceSettings settings{light, view, L0, s.style.edgeWeight, s.falloff, s.bias};
    const FinDebug debug(in.debugDir, s.technique, view);
    const DepthMapSettings hardSettings{s.resolution, DepthLayer::First, polygonOffsetFor(s.bias)};
    int layersDrawn = 0;
    for (int layer = 0; layer < layering.layers.count(); ++layer) {
        const LayerContents& c = layering.contents[layer];
        if (c.empty()) continue;   // lit everywhere: nothing to combine
        ++layersDrawn;
        const DepthMap hard = renderDepthMap(in.world.positions, c.geometry, view, hardSettings, in.simd);
        PenumbraMap inner;
        if (s.style.innerFins) inner = renderPenumbraMap(fins.inner, c.innerFins, view, s.resolution, FinKind::Inner, in.simd);
        const PenumbraMap outer = renderPenumbraMap(fins.outer, c.outerFins, view, s.resolution, FinKind::Outer, in.simd);
        buffer.combineLayer({hard, s.style.innerFins ? &inner : nullptr, outer}, settings);
        debug.writeLayer(layer, hard, s.style.innerFins ? &inner : nullptr, outer, s.style.edgeWeight, in.gbuffer,
                         buffer.values());
    }
    const double layersMs = millisecondsSince(start);
    debug.writeFinCoverage(fins, s.resolution, in.simd);
    debug.writePixelLayers(in.gbuffer, in.world, layering.instanceLayer, layering.layers.count());

    out.visibility = buffer.values();
    out.stats = {{"silhouette edges", double(fins.edges.size())},
                 {"inner fin triangles", double(fins.inner.triangles.size())},
                 {"outer fin triangles", double(fins.outer.triangles.size())},
                 {"layers", double(layering.layers.count())},
                 {"layers drawn", double(layersDrawn)},
                 {"resolution", double(s.resolution)},
                 {"light near", view.zNear},
                 {"reference plane L0", L0},
                 {"silhouette and fins ms", finsMs},
                 {"maps and illuminance ms", layersMs}};
    return out;
}

std::vector<ParamSpec> commonParams() {
    return {integerParam("resolution", 1024, kMinMapResolution, kMaxMapResolution,
                         "texels per side of the hard shadow and penumbra maps"),
            choiceParam<Falloff>("falloff", "linear",
                                 {{"linear", Falloff::Linear, "eq. 1"},
                                  {"bernstein", Falloff::Bernstein, "3u^2 - 2u^3, Haines 2001"}},
                                 "penumbra fall-off")};
}

// The disk light and the settings every variant reads; throws std::invalid_argument.
FinSettings commonSettings(const ShadowInputs& in, const std::string& technique, LightPlane& light) {
    if (in.light.type != LightType::Disk) throw std::invalid_argument(technique + ": needs a disk light");
    light = lightPlaneOf(in.light);
    FinSettings s;
    s.technique = technique;
    s.resolution = in.params.integer("resolution");
    s.falloff = in.params.choice<Falloff>("falloff");
    return s;
}

ShadowOutputs runFins(const ShadowInputs& in) {
    LightPlane light;
    FinSettings s = commonSettings(in, "fins", light);
    s.style = {.innerFins = true, .edgeWeight = 0.5f, .sizing = {FinSizing::Kind::LightRadius, light.radius}};
    s.layers = in.params.integer("layers");
    return renderFinShadows(in, light, s);
}

ShadowOutputs runSmoothies(const ShadowInputs& in) {
    LightPlane light;
    FinSettings s = commonSettings(in, "smoothies", light);
    s.style = {.innerFins = false, .edgeWeight = 1.0f,
               .sizing = {FinSizing::Kind::AngularWidth, in.params.real("size")}};
    return renderFinShadows(in, light, s);
}

ShadowOutputs runPenumbraMaps(const ShadowInputs& in) {
    LightPlane light;
    FinSettings s = commonSettings(in, "penumbra-maps", light);
    s.style = {.innerFins = false, .edgeWeight = 1.0f, .sizing = {FinSizing::Kind::LightRadius, light.radius}};
    return renderFinShadows(in, light, s);
}

}  // namespace

Technique finsTechnique() {
    std::vector<ParamSpec> params = commonParams();
    params.push_back(integerParam("layers", 16, 1, kMaxLayers,
                                  "light-space layers of about equal numbers of silhouette edges, section 4.1; "
                                  "1 is the single-layer algorithm of section 3"));
    return {"fins",
            "multi-layered shadow fins (Cai et al. 2006): inner and outer fins, penumbra maps per layer, refined "
            "illuminance buffer; disk lights",
            params, runFins};
}

Technique smoothiesTechnique() {
    std::vector<ParamSpec> params = commonParams();
    params.push_back(realParam("size", 0.06, 1e-4, 1.0,
                               "smoothie width as seen from the light's centre, tangent of the angle; "
                               "0.06 is about the built-in disk (radius 0.5 m) seen from 8 m"));
    return {"smoothies",
            "smoothies (Chan and Durand 2003): hard shadow plus outer fins of one global size; disk lights", params,
            runSmoothies};
}

Technique penumbraMapsTechnique() {
    return {"penumbra-maps",
            "penumbra maps (Wyman and Hansen 2003): hard shadow plus outer fins sized by the light; disk lights",
            commonParams(), runPenumbraMaps};
}

}  // namespace shadowlab
