#include "shadows/deep/volumetric_frame.h"

#include <algorithm>

#include "shadows/debug_buffers.h"
#include "shadows/maps/shadow_map_debug.h"

namespace shadowlab {

const SettingsTable<VolumetricSettings>& volumetricSettingsTable() {
    static const auto table =
        SettingsTable<VolumetricSettings>()
            .include(member(&VolumetricSettings::map), shadowMapSettingsTable())
            .real("transmittance-offset", member(&VolumetricSettings::lookup, &TransmittanceLookup::offsetTexels), 0.0,
                  100.0, "texels the receiver moves along its normal before the transmittance lookup");
    return table;
}

VolumetricFrame beginVolumetricFrame(const ShadowInputs& in, const CasterTransmission& transmission,
                                     const VolumetricSettings& settings, StageTimer& timer) {
    VolumetricFrame frame{pointLightFor(in.light), {}, {}};
    frame.layers = renderVolumetricLayers(in, frame.light, transmission,
                                     {settings.map.resolution, polygonOffsetFor(settings.map.bias)});
    timer.lap("layers");
    // The opaque map read in place, the one map of the lookup.
    ShadowLookup opaque = lookUpShadows(in.gbuffer, in.camera(), frame.light, std::span(&frame.layers.opaque, 1),
                                        OneMap{}, settings.map.bias, makePcfKernel(settings.map.filter), in.simd);
    frame.opaqueV = std::move(opaque.visibility);
    timer.lap("opaque_lookup");
    return frame;
}

void addVolumetricStats(const VolumetricFrame& frame, double bytesPerTexel, std::vector<TechniqueStat>& stats) {
    const VolumetricLayers& layers = frame.layers;
    const double texels = double(layers.size()) * double(layers.size());
    uint32_t most = 0;
    for (size_t t = 0; t + 1 < layers.start.size(); ++t) most = std::max(most, layers.eventCount(t));
    stats.push_back({"resolution_texels", double(layers.size())});
    stats.push_back({"translucent_fragments", double(layers.translucentFragments)});
    stats.push_back({"volume_pieces_count", double(layers.volumePieces)});
    stats.push_back({"events_per_texel_mean_count", double(layers.start.back()) / texels});
    stats.push_back({"events_per_texel_max_count", double(most)});
    stats.push_back({"storage_per_texel_bytes", bytesPerTexel});
}

void writeVolumetricDebug(const ShadowInputs& in, const std::string& technique, const VolumetricFrame& frame) {
    const DebugBuffers debug(in.debugDir, technique);
    if (!debug.enabled()) return;
    writeDepthMap(debug, "opaque-depth", frame.layers.opaque);
    const int size = frame.layers.size();
    std::vector<float> counts(size_t(size) * size_t(size));
    float most = 1.0f;
    for (size_t t = 0; t < counts.size(); ++t) most = std::max(most, counts[t] = float(frame.layers.eventCount(t)));
    debug.write("events-per-texel", size, size, counts, 0.0f, most);
}

}  // namespace shadowlab
