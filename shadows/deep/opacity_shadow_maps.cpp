// `opacity-shadow-maps` (Kim and Neumann 2001, "Opacity shadow maps", EGWR; Real-Time
// Rendering, 4th ed., section 7.8): the optical depth in front of a fixed set of parallel
// slices, uniformly spaced in depth between the nearest and the farthest translucent event,
// stored per texel (the paper's opacity maps, one per slice); a receiver between two slices
// gets the optical depth interpolated linearly between them and T = exp(-tau) (their
// section 3.2). Its known artefact: a layer between two slices is smeared over the gap, so
// a receiver in front of it is partly shadowed by it and one just behind too little; the
// error falls as the slices grow.
#include <cmath>

#include "raster/portable_math.h"
#include "shadows/deep/deep_techniques.h"
#include "shadows/deep/transmittance_curve.h"
#include "shadows/deep/volumetric_frame.h"

namespace shadowlab {
namespace {

struct OpacitySlices {
    int count = 0;
    float first = 0.0f, spacing = 1.0f;   // slice k at depth first + (k + 1) spacing
    std::vector<float> opticalDepth;      // count per texel, slice by slice

    float at(size_t texel, float z) const;
    double bytesPerTexel() const { return double(count) * sizeof(float); }
    void addStats(VolumetricStats& stats) const { stats.most("slices_count", double(count)); }
    void writeDebug(const DebugBuffers& debug, const VolumetricLayers& layers) const;
};

OpacitySlices buildSlices(const VolumetricLayers& layers, int count) {
    OpacitySlices slices;
    slices.count = count;
    slices.first = layers.nearestDepth;
    slices.spacing = std::max(layers.farthestDepth - layers.nearestDepth, 1e-7f) / float(count);
    const size_t texels = layers.start.size() - 1;
    slices.opticalDepth.assign(texels * size_t(count), 0.0f);
    tbb::parallel_for(size_t(0), texels, [&](size_t t) {
        if (layers.eventCount(t) == 0) return;
        for (int k = 0; k < count; ++k) {
            const double z = double(slices.first) + double(k + 1) * double(slices.spacing);
            slices.opticalDepth[t * size_t(count) + size_t(k)] = float(opticalDepthBefore(layers, t, z));
        }
    });
    return slices;
}

float OpacitySlices::at(size_t texel, float z) const {
    const float u = (z - first) / spacing;   // slice k sits at u = k + 1
    if (!(u > 0.0f)) return 1.0f;
    const float* tau = &opticalDepth[texel * size_t(count)];
    if (!(u < float(count))) return float(portable::exp(-double(tau[count - 1])));   // behind the last slice
    const int below = int(u);   // between slice below - 1 (or the start, optical depth 0) and slice below
    const float from = below == 0 ? 0.0f : tau[below - 1], f = u - float(below);
    return float(portable::exp(-double(from + f * (tau[below] - from))));
}

// Four of the slices: the transmittance in front of each.
void OpacitySlices::writeDebug(const DebugBuffers& debug, const VolumetricLayers& layers) const {
    const int size = layers.size();
    for (int k = 0; k < count; k += std::max(1, count / 4)) {
        std::vector<float> image(size_t(size) * size_t(size));
        for (size_t t = 0; t < image.size(); ++t) {
            image[t] = float(portable::exp(-double(opticalDepth[t * size_t(count) + size_t(k)])));
        }
        debug.write("slice-" + std::to_string(k), size, size, image, 0.0f, 1.0f);
    }
}

struct OpacitySettings {
    VolumetricSettings volumetric;
    int slices = 16;
};

const SettingsTable<OpacitySettings>& opacitySettingsTable() {
    using S = OpacitySettings;
    static const auto table = SettingsTable<S>()
                                  .include(member(&S::volumetric), volumetricSettingsTable())
                                  .integer("slices", member(&S::slices), 1, 256, "opacity maps, uniformly spaced in depth");
    return table;
}

ShadowOutputs runOpacityShadowMaps(const ShadowInputs& in) {
    const OpacitySettings s = opacitySettingsTable().read(in.params);
    return runVolumetricFrame(in, s.volumetric, "opacity-shadow-maps", "slices",
                              [&](const VolumetricLayers& layers) { return buildSlices(layers, s.slices); });
}

}  // namespace

Technique opacityShadowMapsTechnique() {
    return {.name = "opacity-shadow-maps",
            .description = "opacity shadow maps (Kim and Neumann 2001): optical depth at uniform depth slices, "
                           "interpolated between them",
            .params = opacitySettingsTable().specs(),
            .run = runOpacityShadowMaps,
            .referenceName = "reference",
            .output = TechniqueOutput::Visibility};
}

}  // namespace shadowlab
