// The fin-shadow pipeline, one function per step of fin_shadows.h.
#include "shadows/fins/fin_shadows.h"

#include <algorithm>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "scenes/edge_adjacency.h"
#include "shading/lights.h"
#include "shadows/depth_map.h"
#include "shadows/fins/fin_layers.h"
#include "shadows/fins/fin_maps.h"
#include "shadows/fins/fins_debug.h"
#include "shadows/maps/shadow_bias.h"
#include "shadows/silhouettes/cut_out_outline.h"
#include "shadows/silhouettes/silhouette.h"
#include "shadows/stage_timer.h"

namespace shadowlab {
namespace {

// What each layer draws: its objects' triangles into the hard shadow map, their fins into
// the penumbra maps (fin_layers.h: objects go whole into one layer).
struct LayerContents {
    std::vector<uint32_t> geometry;   // world triangle indices, in order
    std::vector<glm::uvec3> innerFins, outerFins;
    bool empty() const { return geometry.empty() && innerFins.empty() && outerFins.empty(); }
};

struct Layering {
    LightLayers layers;
    std::vector<int> instanceLayer;
    std::vector<LayerContents> contents;
};

// Steps 1 to 3: what every layer's maps are drawn from.
struct FinScene {
    LightView view;
    double L0 = 0.0;   // the reference receiver plane (section 3.1): the view's far plane
    Fins fins;
    Layering layering;
    size_t cutOutEdges = 0;   // the cards' own silhouette edges, left without fins (cut_out_silhouette_edges)
    size_t outlineEdges = 0;  // the cut-outs' outline edges in their place (cut_out_outline_edges)
    size_t refusedCutOuts = 0;  // cut-out instances with no outline (cut_out_outline_refused_count)
};

// The positions the fins are built from: the world's, then the cut-outs' outline vertices
// (cut_out_outline.h), each outline vertex with its instance. Copied only for cut-outs.
struct FinVertices {
    std::span<const glm::vec3> world;
    std::vector<glm::vec3> withOutline;   // world, then the outline's; empty without an outline
    std::vector<uint32_t> outlineInstance;
    std::span<const glm::vec3> positions() const { return withOutline.empty() ? world : withOutline; }
};

uint32_t instanceOfVertex(const std::vector<InstanceRange>& ranges, const FinVertices& vertices, uint32_t vertex) {
    if (vertex >= vertices.world.size()) return vertices.outlineInstance[vertex - vertices.world.size()];
    const auto after = std::upper_bound(ranges.begin(), ranges.end(), vertex,
                                        [](uint32_t v, const InstanceRange& r) { return v < r.firstVertex; });
    return uint32_t(after - ranges.begin() - 1);
}

// Step 1: the view from the disk's centre along its normal, so that its depth planes are
// parallel to the light's plane.
LightView fitFinView(const ShadowInputs& in, const FinSettings& s) {
    LightFitOptions fit;
    fit.resolution = s.maps.resolution;
    fit.axis = s.light.normal;
    fit.simd = in.simd;
    return fitLightView(pointLightFor(in.light), in.gbuffer, in.casterWorld(), fit);
}

// Step 3: each instance, with its fins, into the layer of its edges' median midpoint.
Layering layerScene(const ShadowInputs& in, const Fins& fins, const FinVertices& vertices, const LightPlane& light,
                    const LightView& view, int layerCount) {
    const std::vector<InstanceRange> ranges = instanceRanges(in.casters().scene());
    std::vector<uint32_t> edgeInstance;
    for (const SilhouetteEdge& e : fins.edges) edgeInstance.push_back(instanceOfVertex(ranges, vertices, e.from));
    std::vector<double> fallback;   // instances without silhouette edges: their first vertex
    for (const InstanceRange& r : ranges) fallback.push_back(light.distance(glm::dvec3(in.casterWorld().positions[r.firstVertex])));
    Layering l{LightLayers(fins.midpointDistance, view.zNear, view.zFar, layerCount), {}, {}};
    l.instanceLayer = instanceLayers(l.layers, fins.midpointDistance, edgeInstance, fallback);
    l.contents.resize(l.layers.count());
    for (size_t i = 0; i < ranges.size(); ++i) {
        std::vector<uint32_t>& geometry = l.contents[l.instanceLayer[i]].geometry;
        for (uint32_t k = 0; k < ranges[i].triangleCount; ++k) geometry.push_back(ranges[i].firstTriangle + k);
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

// Removes the silhouette edges of cut-outs and returns how many: a card's edges are not the
// outline of its leaves, whose hard shadow the layer's depth map draws with its holes; fins
// on them would add a band of penumbra around the card's square (docs/cut-outs.md). The
// outline takes their place.
size_t dropCutOutEdges(std::vector<SilhouetteEdge>& edges, const ShadowInputs& in, const FinVertices& vertices) {
    const WorldGeometry& world = in.casterWorld();
    if (world.cutOuts.empty()) return 0;
    const std::vector<InstanceRange> ranges = instanceRanges(in.casters().scene());
    return std::erase_if(edges, [&](const SilhouetteEdge& e) {
        const InstanceRange& r = ranges[instanceOfVertex(ranges, vertices, e.from)];
        return world.triangleCutOut[r.firstTriangle] >= 0;   // an edge's instance has triangles
    });
}

// Step 2 for cut-outs: their outline's vertices after the world's, its edges after the meshes'.
void addCutOutOutline(const CutOutOutline& outline, FinVertices& vertices, std::vector<SilhouetteEdge>& silhouette) {
    if (outline.positions.empty()) return;
    vertices.withOutline.assign(vertices.world.begin(), vertices.world.end());
    vertices.withOutline.insert(vertices.withOutline.end(), outline.positions.begin(), outline.positions.end());
    vertices.outlineInstance = outline.vertexInstance;
    const uint32_t base = uint32_t(vertices.world.size());
    for (const SilhouetteEdge& e : outline.edges) silhouette.push_back({base + e.from, base + e.to});
}

// Steps 1 to 3: the view, the fins of the silhouette edges w.r.t. the light's centre, the layers.
FinScene buildFinScene(const ShadowInputs& in, const FinSettings& s, StageTimer& timer) {
    const LightView view = fitFinView(in, s);
    const double L0 = view.zFar;
    const glm::dvec4 centre(s.light.centre, 1.0);
    const WorldGeometry& world = in.casterWorld();
    std::vector<SilhouetteEdge> silhouette =
        sceneSilhouette(in.casters().scene(), world, in.casters().edgeAdjacency(), centre);
    FinVertices vertices{world.positions, {}, {}};
    const size_t cutOutEdges = dropCutOutEdges(silhouette, in, vertices);
    CutOutOutline outline;
    if (!world.cutOuts.empty()) {
        timer.lap("silhouette_and_fins");   // the rest of the stage adds to it (renderFinShadows)
        outline = cutOutOutline(in.casters().scene(), world, in.casters().edgeAdjacency(), centre);
        addCutOutOutline(outline, vertices, silhouette);
        timer.lap("cut_out_outline");
    }
    Fins fins = buildFins(vertices.positions(), silhouette, s.light, L0, s.style);
    Layering layering = layerScene(in, fins, vertices, s.light, view, s.layers);
    return {view, L0, std::move(fins), std::move(layering), cutOutEdges, outline.edges.size(), outline.refusedInstances};
}

// 1 where the light can reach a surface (lightReaches: it faces the disk's centre), else 0.
std::vector<uint8_t> facingLight(const GBuffer& g, const Light& light) {
    std::vector<uint8_t> facing(g.pixelCount(), 0);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, g.pixelCount(), 16384), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t k = r.begin(); k != r.end(); ++k) facing[k] = g.hit[k] && lightReaches(light, g.position[k], g.normal[k]);
    });
    return facing;
}

// Step 4, near to far; layers without objects or fins are lit everywhere and skipped.
// Returns the number of layers drawn.
int drawLayers(const ShadowInputs& in, const FinScene& scene, const FinSettings& s, const FinDebug& debug,
               IlluminanceBuffer& buffer, StageTimer& timer) {
    const IlluminanceSettings settings{s.light, scene.view, scene.L0, s.style.edgeWeight, s.maps.falloff, in.simd};
    // Slope-scaled, the shadow map's default: the illuminance compares receivers where they are.
    const DepthMapSettings hardSettings{s.maps.resolution, DepthLayer::First, polygonOffsetFor(BiasSettings{}), {}};
    int drawn = 0;
    for (int layer = 0; layer < scene.layering.layers.count(); ++layer) {
        const LayerContents& c = scene.layering.contents[layer];
        if (c.empty()) continue;
        ++drawn;
        const DepthMap hard = renderDepthMap(in.casterWorld(), c.geometry, scene.view, hardSettings, in.simd);
        timer.lap("hard_maps");
        PenumbraMap inner;
        if (s.style.innerFins) {
            inner = renderPenumbraMap(scene.fins.inner, c.innerFins, scene.view, s.maps.resolution, FinKind::Inner,
                                      in.simd);
        }
        const PenumbraMap outer =
            renderPenumbraMap(scene.fins.outer, c.outerFins, scene.view, s.maps.resolution, FinKind::Outer, in.simd);
        const PenumbraMap* innerOrNone = s.style.innerFins ? &inner : nullptr;
        timer.lap("penumbra_maps");
        buffer.combineLayer({hard, innerOrNone, outer}, settings);
        timer.lap("illuminance");
        debug.writeLayer(layer, hard, innerOrNone, outer, s.style.edgeWeight, in.gbuffer, buffer.values());
        if (debug.enabled()) timer.lap("debug_buffers");   // not the next layer's hard map
    }
    return drawn;
}

void addFinStats(const FinScene& scene, const FinSettings& s, int layersDrawn, std::vector<TechniqueStat>& stats) {
    stats.insert(stats.end(), {{"silhouette_edges", double(scene.fins.edges.size())},
                               {"inner_fin_triangles", double(scene.fins.inner.triangles.size())},
                               {"outer_fin_triangles", double(scene.fins.outer.triangles.size())},
                               {"layers_count", double(scene.layering.layers.count())},
                               {"layers_drawn_count", double(layersDrawn)},
                               {"resolution_texels", double(s.maps.resolution)},
                               {"light_near_m", scene.view.zNear},
                               {"reference_plane_l0_m", scene.L0}});
    if (scene.cutOutEdges > 0) stats.push_back({"cut_out_silhouette_edges", double(scene.cutOutEdges)});
    if (scene.outlineEdges > 0) stats.push_back({"cut_out_outline_edges", double(scene.outlineEdges)});
    if (scene.refusedCutOuts > 0) stats.push_back({"cut_out_outline_refused_count", double(scene.refusedCutOuts)});
}

}  // namespace

const SettingsTable<FinMapSettings>& finMapSettingsTable() {
    using S = FinMapSettings;
    static const auto table =
        SettingsTable<S>()
            .include(member(&S::resolution), mapResolutionTable("texels per side of the hard shadow and penumbra maps"))
            .choice("falloff", member(&S::falloff),
                    {{"linear", Falloff::Linear, "eq. 1"},
                     {"bernstein", Falloff::Bernstein, "3u^2 - 2u^3, Haines 2001"}},
                    "penumbra fall-off");
    return table;
}

FinSettings finSettings(const ShadowInputs& in, const std::string& technique, const FinMapSettings& maps) {
    if (in.light.type != LightType::Disk) throw std::invalid_argument(technique + ": needs a disk light");
    FinSettings s;
    s.technique = technique;
    s.light = lightPlaneOf(in.light);
    s.maps = maps;
    return s;
}

ShadowOutputs renderFinShadows(const ShadowInputs& in, const FinSettings& s) {
    if (!anyReachable(in.gbuffer, in.light)) return unlitOutputs(in.gbuffer);   // settings checked by finSettings
    StageTimer timer;
    const FinScene scene = buildFinScene(in, s, timer);
    timer.lap("silhouette_and_fins");

    IlluminanceBuffer buffer(in.gbuffer, facingLight(in.gbuffer, in.light));
    timer.lap("facing");
    const FinDebug debug(in.debugDir, s.technique, scene.view);
    const int layersDrawn = drawLayers(in, scene, s, debug, buffer, timer);
    debug.writeFinCoverage(scene.fins, s.maps.resolution, in.simd);
    debug.writePixelLayers(in.gbuffer, in.receiverWorld(), scene.layering.instanceLayer, scene.layering.layers.count());

    ShadowOutputs out;
    out.visibility = buffer.values();
    addFinStats(scene, s, layersDrawn, out.stats);
    timer.appendTo(out.stats);
    return out;
}

}  // namespace shadowlab
