// `adaptive-volumetric-shadow-maps` (Salvi, Vidimce, Lauritzen and Lefohn 2010, "Adaptive
// volumetric shadow maps", EGSR; Real-Time Rendering, 4th ed., section 7.8): a fixed number
// of (depth, transmittance) nodes per texel, compressed on the fly as occluders arrive
// rather than from the whole list (adaptive_nodes.h): each surface fragment or volume piece
// is a segment whose two nodes go in, and when a texel holds too many nodes the interior
// node whose removal changes the area under the curve least goes (section 3.2). The curve
// is linear between nodes (section 3.3). Occluders arrive in drawing order (the triangles'
// order, then the volume pieces front to back), which is the same on every thread count,
// so the bytes are too; on a GPU the order, and so the result, varies from frame to frame.
#include <algorithm>

#include "raster/portable_math.h"
#include "shadows/debug_buffers.h"
#include "shadows/deep/adaptive_nodes.h"
#include "shadows/deep/curve_plot.h"
#include "shadows/deep/deep_techniques.h"
#include "shadows/deep/transmittance_curve.h"
#include "shadows/deep/volumetric_settings.h"

namespace shadowlab {
namespace {

struct AdaptiveMap {
    int capacity = 0;
    std::vector<CurveVertex> nodes;   // capacity (+2 of room) per texel
    std::vector<uint8_t> counts;
};

// Texel t's events in arrival order: the surfaces by triangle, then the volume pieces
// front to back.
void arrivalOrder(const LightLayers& layers, size_t t, std::vector<uint32_t>& order) {
    order.clear();
    for (uint32_t e = layers.start[t]; e < layers.start[t + 1]; ++e) order.push_back(e);
    std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
        const bool volumeA = layers.triangle[a] == LightLayers::kVolumePiece, volumeB = layers.triangle[b] == LightLayers::kVolumePiece;
        if (volumeA != volumeB) return volumeB;
        return !volumeA && layers.triangle[a] < layers.triangle[b];
    });
}

AdaptiveMap buildAdaptiveMap(const LightLayers& layers, int capacity) {
    AdaptiveMap map;
    map.capacity = capacity;
    const size_t texels = layers.start.size() - 1, stride = size_t(capacity) + 2;
    map.nodes.assign(texels * stride, {1.0f, 1.0f});
    map.counts.assign(texels, 0);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, texels), [&](const tbb::blocked_range<size_t>& range) {
        std::vector<uint32_t> order;
        for (size_t t = range.begin(); t < range.end(); ++t) {
            arrivalOrder(layers, t, order);
            AdaptiveNodes list{&map.nodes[t * stride], 0, capacity};
            for (uint32_t e : order) {
                list.insertSegment(layers.depthNear[e], layers.depthFar[e], float(portable::exp(-double(layers.opticalDepth[e]))));
            }
            map.counts[t] = uint8_t(list.count);
        }
    });
    return map;
}

// T(z): 1 in front of the first node, linear between nodes, the last node's value behind.
float nodeTransmittance(const AdaptiveMap& map, size_t texel, float z) {
    const CurveVertex* nodes = &map.nodes[texel * (size_t(map.capacity) + 2)];
    return transmittanceAt({nodes, map.counts[texel]}, z);
}

void writeNodeCounts(const ShadowInputs& in, const LightLayers& layers, const AdaptiveMap& map) {
    const DebugBuffers debug(in.debugDir, "adaptive-volumetric-shadow-maps");
    if (!debug.enabled()) return;
    const std::vector<float> counts(map.counts.begin(), map.counts.end());
    debug.write("nodes-per-texel", layers.size(), layers.size(), counts, 0.0f, float(map.capacity));
}

ShadowOutputs runAdaptiveVolumetricShadowMaps(const ShadowInputs& in) {
    const VolumetricSettings settings = readVolumetricSettings(in.params);
    const int capacity = in.params.integer("nodes");
    if (!anySurface(in.gbuffer)) return unlitOutputs(in.gbuffer);
    StageTimer timer;
    const CasterTransmission transmission(in.casters().scene(), in.casterWorld());
    const VolumetricFrame frame = beginVolumetricFrame(in, transmission, settings, timer);
    const AdaptiveMap map = buildAdaptiveMap(frame.layers, capacity);
    timer.lap("nodes");
    const auto curve = [&](size_t texel, float z) { return nodeTransmittance(map, texel, z); };
    ShadowOutputs out;
    out.visibility = lookUpTransmittance(in.gbuffer, frame.layers.opaque, frame.opaqueV, settings.lookup, curve);
    timer.lap("lookup");
    addVolumetricStats(frame, double(capacity) * sizeof(CurveVertex), out.stats);
    out.stats.push_back({"nodes_count", double(capacity)});
    timer.appendTo(out.stats);
    writeVolumetricDebug(in, "adaptive-volumetric-shadow-maps", frame);
    writeNodeCounts(in, frame.layers, map);
    plotCurves(in.debugDir, "adaptive-volumetric-shadow-maps", frame.layers, curve);
    return out;
}

}  // namespace

Technique adaptiveVolumetricShadowMapsTechnique() {
    std::vector<ParamSpec> params = volumetricParamSpecs();
    params.push_back(integerParam("nodes", 8, 2, 64, "(depth, transmittance) nodes per texel; a surface takes two"));
    return {.name = "adaptive-volumetric-shadow-maps",
            .description = "adaptive volumetric shadow maps (Salvi et al. 2010): a fixed number of nodes per texel, "
                           "compressed as fragments arrive",
            .params = params,
            .run = runAdaptiveVolumetricShadowMaps,
            .referenceName = "reference",
            .output = TechniqueOutput::Visibility};
}

}  // namespace shadowlab
