// `deep-shadow-maps` (Lokovic and Veach 2000, "Deep shadow maps", SIGGRAPH): per texel the
// transmittance curve itself (section 3), built from every fragment and volume piece the
// texel sees (transmittance_curve.h) and compressed to few vertices within an error
// tolerance (section 4.2, curve_compression.h); a texel keeping more than `max-vertices`
// is compressed again at twice the tolerance until it fits. Lookups are filtered: the four
// nearest texels' curves, evaluated at the receiver's depth, blended bilinearly (section 4.1).
#include <algorithm>

#include <tbb/parallel_for.h>

#include "shadows/deep/curve_compression.h"
#include "shadows/deep/deep_techniques.h"
#include "shadows/deep/volumetric_frame.h"

namespace shadowlab {
namespace {

struct DeepMap {
    std::vector<uint32_t> start;          // per texel, into vertices
    std::vector<CurveVertex> vertices;
    uint32_t mostVertices = 0;
    float largestTolerance = 0.0f;        // after any doubling

    std::span<const CurveVertex> curve(size_t texel) const {
        return {vertices.data() + start[texel], start[texel + 1] - start[texel]};
    }
    float at(size_t texel, float z) const { return transmittanceAt(curve(texel), z); }
    double texels() const { return double(start.size() - 1); }
    double bytesPerTexel() const {
        return (double(vertices.size()) * sizeof(CurveVertex) + texels() * sizeof(uint32_t)) / texels();
    }
    void addStats(VolumetricStats& stats) const {
        stats.mean("vertices_per_texel_mean_count", double(vertices.size()) / texels());
        stats.most("vertices_per_texel_max_count", double(mostVertices));
        stats.most("largest_tolerance_ratio", double(largestTolerance));
    }
    void writeDebug(const DebugBuffers& debug, const VolumetricLayers& layers) const {
        std::vector<float> counts(start.size() - 1);
        for (size_t t = 0; t < counts.size(); ++t) counts[t] = float(start[t + 1] - start[t]);
        debug.write("vertices-per-texel", layers.size(), layers.size(), counts, 0.0f,
                    float(std::max<uint32_t>(mostVertices, 1)));
    }
};

struct CompressedTexel {
    uint32_t vertices;
    float tolerance;
};

// Texel t's curve, compressed until it has at most maxVertices.
CompressedTexel compressTexel(const VolumetricLayers& layers, size_t t, float tolerance, int maxVertices,
                              ExactCurves& curves, std::vector<CurveVertex>& exact, std::vector<CurveVertex>& out) {
    curves.build(layers, t, exact);
    compressCurve(exact, tolerance, out);
    while (out.size() > size_t(maxVertices)) {
        tolerance = tolerance > 0.0f ? 2.0f * tolerance : 1.0f / 1024.0f;   // a tolerance of 1 keeps 2
        compressCurve(exact, tolerance, out);
    }
    return {uint32_t(out.size()), tolerance};
}

DeepMap buildDeepMap(const VolumetricLayers& layers, float tolerance, int maxVertices) {
    const int size = layers.size();
    std::vector<std::vector<CurveVertex>> rows(static_cast<size_t>(size));
    std::vector<CompressedTexel> texels(size_t(size) * size_t(size));
    tbb::parallel_for(0, size, [&](int y) {
        ExactCurves curves;
        std::vector<CurveVertex> exact, compressed;
        for (int x = 0; x < size; ++x) {
            const size_t t = size_t(y) * size_t(size) + size_t(x);
            texels[t] = compressTexel(layers, t, tolerance, maxVertices, curves, exact, compressed);
            rows[size_t(y)].insert(rows[size_t(y)].end(), compressed.begin(), compressed.end());
        }
    });
    DeepMap map;
    map.start.assign(texels.size() + 1, 0);
    for (size_t t = 0; t < texels.size(); ++t) {
        map.start[t + 1] = map.start[t] + texels[t].vertices;
        map.mostVertices = std::max(map.mostVertices, texels[t].vertices);
        map.largestTolerance = std::max(map.largestTolerance, texels[t].vertices ? texels[t].tolerance : 0.0f);
    }
    // Each row's curves copied to their place in parallel: the same bytes for any thread count.
    map.vertices.resize(map.start.back());
    tbb::parallel_for(0, size, [&](int y) {
        const std::vector<CurveVertex>& row = rows[size_t(y)];
        std::copy(row.begin(), row.end(), map.vertices.begin() + map.start[size_t(y) * size_t(size)]);
    });
    return map;
}

struct DeepSettings {
    VolumetricSettings volumetric;
    float tolerance = 0.02f;   // of the curve's compression
    int maxVertices = 16;      // per texel's curve
};

const SettingsTable<DeepSettings>& deepSettingsTable() {
    using S = DeepSettings;
    static const auto table =
        SettingsTable<S>()
            .include(member(&S::volumetric), volumetricSettingsTable())
            .real("tolerance", member(&S::tolerance), 0.0, 1.0, "largest change of transmittance compression may make")
            .integer("max-vertices", member(&S::maxVertices), 2, 1024, "vertices a texel's curve may keep");
    return table;
}

ShadowOutputs runDeepShadowMaps(const ShadowInputs& in) {
    const DeepSettings s = deepSettingsTable().read(in.params);
    return runVolumetricFrame(in, s.volumetric, "deep-shadow-maps", "curves", [&](const VolumetricLayers& layers) {
        return buildDeepMap(layers, s.tolerance, s.maxVertices);
    });
}

}  // namespace

Technique deepShadowMapsTechnique() {
    return {.name = "deep-shadow-maps",
            .description = "deep shadow maps (Lokovic and Veach 2000): each texel's transmittance curve from all "
                           "fragments, compressed within a tolerance, filtered lookups",
            .params = deepSettingsTable().specs(),
            .run = runDeepShadowMaps,
            .referenceName = "reference",
            .output = TechniqueOutput::Visibility};
}

}  // namespace shadowlab
