// The transmittance curves of chosen texels as plots (--debug-buffers): for the three
// texels with the most events, T(z) of the exact curve (transmittance_curve.h) against the
// technique's own, sampled at 256 depths across the texel's events, written as
// <technique>-curves.csv and one SVG per texel, <technique>-curve-<x>-<y>.svg, each name
// ended by the map's suffix (a cube face's "-face-px"): where a technique's storage departs
// from the truth, and by how much, at a glance.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "shading/luminance.h"
#include "shadows/deep/light_layers.h"
#include "shadows/deep/transmittance_curve.h"

namespace shadowlab {

// One value of a curve: a transmittance, or the luminance of one per channel.
inline float luminanceOf(float value) { return value; }
inline float luminanceOf(const glm::vec3& value) { return luminance(value); }

struct SampledCurve {
    size_t texel;
    std::vector<float> depth, exact, technique;
};

// The texels with the most events (at most `count`; the first on a tie), most first.
std::vector<size_t> busiestTexels(const VolumetricLayers& layers, int count);

void writeCurvePlots(const std::filesystem::path& directory, const std::string& technique, const std::string& suffix,
                     int mapSize, const std::vector<SampledCurve>& curves);

// Samples the exact and the technique's curve, curve(texel, depth), at the busiest texels
// and writes them; nothing without a debug directory.
template <class Curve>
void plotCurves(const std::filesystem::path& directory, const std::string& technique, const std::string& suffix,
                const VolumetricLayers& layers, const Curve& curve) {
    if (directory.empty()) return;
    constexpr int kSamples = 256;
    std::vector<SampledCurve> curves;
    ExactCurves exact;
    std::vector<CurveVertex> vertices;
    for (size_t texel : busiestTexels(layers, 3)) {
        exact.build(layers, texel, vertices);
        if (vertices.empty()) continue;
        const float first = vertices.front().depth, last = vertices.back().depth;
        const float margin = 0.05f * (last - first) + 1e-6f;
        SampledCurve sampled{texel, {}, {}, {}};
        for (int s = 0; s < kSamples; ++s) {
            const float z = first - margin + (last - first + 2.0f * margin) * float(s) / float(kSamples - 1);
            sampled.depth.push_back(z);
            sampled.exact.push_back(transmittanceAt(vertices, z));
            sampled.technique.push_back(luminanceOf(curve(texel, z)));
        }
        curves.push_back(std::move(sampled));
    }
    writeCurvePlots(directory, technique, suffix, layers.size(), curves);
}

}  // namespace shadowlab
