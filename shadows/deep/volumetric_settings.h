// What every volumetric shadow map shares: the light's view and its opaque map (a shadow
// map's resolution, bias and filter, shadows/maps/shadow_map_settings.h), the normal offset
// of the transmittance lookup, and the passes they run in order: the light's layers, the
// opaque lookup, the technique's per-texel storage and its lookup.
#pragma once

#include <string>
#include <vector>

#include "shadows/caster_transmission.h"
#include "shadows/deep/light_layers.h"
#include "shadows/deep/transmittance_lookup.h"
#include "shadows/maps/shadow_map_settings.h"
#include "shadows/stage_timer.h"
#include "shadows/technique.h"

namespace shadowlab {

struct VolumetricSettings {
    ShadowMapSettings map;
    TransmittanceLookup lookup;
};

// The shadow map's parameters at a resolution of 512 (each texel holds a list), and
// `transmittance-offset`.
std::vector<ParamSpec> volumetricParamSpecs();
VolumetricSettings readVolumetricSettings(const TechniqueParams& params);

// The stages before a technique's own: the light's layers (stage `layers`) and the opaque
// lookup (stage `opaque_lookup`), for a hard light (an area light's centre stands in).
struct VolumetricFrame {
    Light light;
    LightLayers layers;
    std::vector<float> opaqueV;
};
VolumetricFrame beginVolumetricFrame(const ShadowInputs& in, const CasterTransmission& transmission,
                                     const VolumetricSettings& settings, StageTimer& timer);

// The stats every volumetric technique reports: fragments, volume pieces, events per texel,
// and the technique's bytes per texel.
void addVolumetricStats(const VolumetricFrame& frame, double bytesPerTexel, std::vector<TechniqueStat>& stats);

// Debug buffers every technique writes: the opaque map and the number of events per texel.
void writeVolumetricDebug(const ShadowInputs& in, const std::string& technique, const VolumetricFrame& frame);

}  // namespace shadowlab
