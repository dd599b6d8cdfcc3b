// What every volumetric shadow map shares: the light's view and its opaque map (a shadow
// map's resolution, bias and filter, shadows/maps/shadow_map_settings.h), the normal offset
// of the transmittance lookup, and the frame they all run: the light's layers, the opaque
// lookup, the technique's per-texel storage and its lookup (runVolumetricFrame).
#pragma once

#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "shading/luminance.h"
#include "shadows/caster_transmission.h"
#include "shadows/debug_buffers.h"
#include "shadows/deep/curve_plot.h"
#include "shadows/deep/light_layers.h"
#include "shadows/deep/transmittance_lookup.h"
#include "shadows/maps/shadow_map_settings.h"
#include "shadows/stage_timer.h"
#include "shadows/technique.h"

namespace shadowlab {

struct VolumetricSettings {
    // Each texel holds a list or a curve, not one depth: a smaller map by default.
    ShadowMapSettings map{.resolution = 512};
    TransmittanceLookup lookup;
};

// The shadow map's parameters, and `transmittance-offset`.
const SettingsTable<VolumetricSettings>& volumetricSettingsTable();

// The stages before a technique's own: the light's layers (stage `layers`) and the opaque
// lookup (stage `opaque_lookup`), for a hard light (an area light's centre stands in).
struct VolumetricFrame {
    Light light;
    VolumetricLayers layers;
    std::vector<float> opaqueV;
};
VolumetricFrame beginVolumetricFrame(const ShadowInputs& in, const CasterTransmission& transmission,
                                     const VolumetricSettings& settings, StageTimer& timer);

// The stats every volumetric technique reports: fragments, volume pieces, events per texel,
// and the technique's bytes per texel.
void addVolumetricStats(const VolumetricFrame& frame, double bytesPerTexel, std::vector<TechniqueStat>& stats);

// Debug buffers every technique writes: the opaque map and the number of events per texel.
void writeVolumetricDebug(const ShadowInputs& in, const std::string& technique, const VolumetricFrame& frame);

// One frame of a volumetric technique with its settings as read: the shared stages
// (beginVolumetricFrame), what the technique keeps per texel, `build(layers)` (timed as
// `stage`), the lookup of its `at(texel, depth)` at every receiver (a transmittance, or one
// per channel, which the frame shades with and whose luminance is V), and the figures and
// buffers every technique reports with the storage's own (`bytesPerTexel()`,
// `addStats(stats)`, `writeDebug(debug, layers)`).
template <class Build>
ShadowOutputs runVolumetricFrame(const ShadowInputs& in, const VolumetricSettings& settings, const std::string& technique,
                                 const char* stage, const Build& build) {
    if (!anyReachable(in.gbuffer, in.light)) return unlitOutputs(in.gbuffer);   // settings checked first
    StageTimer timer;
    const CasterTransmission transmission(in.casters().scene(), in.casterWorld());
    const VolumetricFrame frame = beginVolumetricFrame(in, transmission, settings, timer);
    const auto storage = build(frame.layers);
    timer.lap(stage);
    const auto curve = [&](size_t texel, float z) { return storage.at(texel, z); };
    auto passed = lookUpTransmittance(in.gbuffer, frame.layers.opaque, frame.opaqueV, settings.lookup, curve);
    ShadowOutputs out;
    if constexpr (std::is_same_v<decltype(passed), std::vector<glm::vec3>>) {
        out.visibility.resize(passed.size());
        for (size_t k = 0; k < passed.size(); ++k) out.visibility[k] = luminance(passed[k]);
        out.colouredVisibility = std::move(passed);
    } else {
        out.visibility = std::move(passed);
    }
    timer.lap("lookup");
    addVolumetricStats(frame, storage.bytesPerTexel(), out.stats);
    storage.addStats(out.stats);
    timer.appendTo(out.stats);
    writeVolumetricDebug(in, technique, frame);
    const DebugBuffers debug(in.debugDir, technique);
    if (debug.enabled()) storage.writeDebug(debug, frame.layers);
    plotCurves(in.debugDir, technique, frame.layers, curve);
    return out;
}

}  // namespace shadowlab
