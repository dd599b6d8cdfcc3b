// The settings shadow-map and csm share (--param name=value), with their defaults and the
// reasons for them. Each technique adds its own parameters to these.
#pragma once

#include <vector>

#include "shadows/depth_map.h"
#include "shadows/maps/pcf.h"
#include "shadows/maps/shadow_bias.h"
#include "shadows/settings_table.h"

namespace shadowlab {

struct ShadowMapSettings {
    int resolution = 2048;
    DepthLayer layer = DepthLayer::First;
    BiasSettings bias = {};
    FilterSettings filter = {};
};

// The bias rows (`bias`, `constant-bias`, `slope-factor`, `slope-units`, `normal-offset`),
// which every technique comparing depths in a map shares.
const SettingsTable<BiasSettings>& biasSettingsTable();

// The PCF rows (`filter`, `grid-size`, `poisson-taps`, `poisson-radius`), which every
// technique filtering a map's compares shares.
const SettingsTable<FilterSettings>& filterSettingsTable();
// The choices of a Poisson disk's per-pixel rotation (pcf.h, RotationNoise): hash, ign.
const std::vector<Choice<RotationNoise>>& rotationNoiseChoices();

// Its parameters (docs/shadow-maps.md), each bound to its member; the defaults above.
const SettingsTable<ShadowMapSettings>& shadowMapSettingsTable();

DepthMapSettings depthMapSettings(const ShadowMapSettings& settings);

}  // namespace shadowlab
