// `adaptive-volumetric-shadow-maps` (Salvi, Vidimce, Lauritzen and Lefohn 2010, "Adaptive
// volumetric shadow maps", EGSR; Real-Time Rendering, 4th ed., section 7.8): a fixed number
// of (depth, transmittance) nodes per texel, compressed on the fly as occluders arrive
// rather than from the whole list (adaptive_nodes.h): each surface fragment or volume piece
// is a segment whose two nodes go in, and when a texel holds too many nodes the interior
// node whose removal changes the area under the curve least goes (section 3.2). The curve
// is linear between nodes (section 3.3). Occluders arrive in a fixed order, the surfaces by
// triangle index and then the volume pieces front to back, the same on every thread count,
// so the bytes are too; on a GPU they arrive as rasterized, and the result varies from frame
// to frame.
#include <algorithm>

#include "raster/portable_math.h"
#include "shadows/deep/adaptive_nodes.h"
#include "shadows/deep/deep_techniques.h"
#include "shadows/deep/transmittance_curve.h"
#include "shadows/deep/volumetric_frame.h"

namespace shadowlab {
namespace {

struct AdaptiveMap {
    int capacity = 0;
    std::vector<CurveVertex> nodes;   // capacity (+2 of room) per texel
    std::vector<uint8_t> counts;

    // T(z): 1 in front of the first node, linear between nodes, the last node's value behind.
    float at(size_t texel, float z) const {
        return transmittanceAt({&nodes[texel * (size_t(capacity) + 2)], counts[texel]}, z);
    }
    double bytesPerTexel() const { return double(capacity) * sizeof(CurveVertex); }
    void addStats(VolumetricStats& stats) const { stats.most("nodes_count", double(capacity)); }
    void writeDebug(const DebugBuffers& debug, const VolumetricLayers& layers) const {
        const std::vector<float> perTexel(counts.begin(), counts.end());
        debug.write("nodes-per-texel", layers.size(), layers.size(), perTexel, 0.0f, float(capacity));
    }
};

// Texel t's events in arrival order: the surfaces by triangle index, then the volume
// pieces front to back.
void arrivalOrder(const VolumetricLayers& layers, size_t t, std::vector<uint32_t>& order) {
    order.clear();
    for (uint32_t e = layers.start[t]; e < layers.start[t + 1]; ++e) order.push_back(e);
    std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
        const bool volumeA = layers.triangle[a] == VolumetricLayers::kVolumePiece;
        const bool volumeB = layers.triangle[b] == VolumetricLayers::kVolumePiece;
        if (volumeA != volumeB) return volumeB;
        return !volumeA && layers.triangle[a] < layers.triangle[b];
    });
}

AdaptiveMap buildAdaptiveMap(const VolumetricLayers& layers, int capacity) {
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
                const float passed = float(portable::exp(-double(layers.opticalDepth[e])));
                list.insertSegment(layers.depthNear[e], layers.depthFar[e], passed);
            }
            map.counts[t] = uint8_t(list.count);
        }
    });
    return map;
}

struct AdaptiveSettings {
    VolumetricSettings volumetric;
    int nodes = 8;   // per texel
};

const SettingsTable<AdaptiveSettings>& adaptiveSettingsTable() {
    using S = AdaptiveSettings;
    static const auto table =
        SettingsTable<S>()
            .include(member(&S::volumetric), volumetricSettingsTable())
            .integer("nodes", member(&S::nodes), 2, 64, "(depth, transmittance) nodes per texel; a surface takes two");
    return table;
}

ShadowOutputs runAdaptiveVolumetricShadowMaps(const ShadowInputs& in) {
    const AdaptiveSettings s = adaptiveSettingsTable().read(in.params);
    return runVolumetricFrame(in, s.volumetric, "adaptive-volumetric-shadow-maps", "nodes",
                              [&](const VolumetricLayers& layers) { return buildAdaptiveMap(layers, s.nodes); });
}

}  // namespace

Technique adaptiveVolumetricShadowMapsTechnique() {
    return {.name = "adaptive-volumetric-shadow-maps",
            .description = "adaptive volumetric shadow maps (Salvi et al. 2010): a fixed number of nodes per texel, "
                           "compressed as fragments arrive",
            .params = adaptiveSettingsTable().specs(),
            .run = runAdaptiveVolumetricShadowMaps,
            .referenceName = "reference",
            .output = TechniqueOutput::Visibility};
}

}  // namespace shadowlab
