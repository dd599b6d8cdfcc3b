// Percentage-closer soft shadows as a pass (pcss.cpp): the `pcss` technique runs it, and so
// does the hybrid izb-pcss (shadows/hybrid), which also reads the blocker distance it finds
// per pixel to choose between the hard and the soft shadow.
#pragma once

#include <optional>
#include <vector>

#include "shadows/filtered/blocker_search.h"
#include "shadows/filtered/soft_shadow_map.h"
#include "shadows/maps/min_max_hierarchy.h"
#include "shadows/maps/pcf.h"
#include "shadows/technique.h"

namespace shadowlab {

struct PcssSettings {
    int resolution = kSoftMapResolution;   // texels per side of the map
    BlockerSearchSettings search;
    int filterTaps = 32;            // Poisson taps of the PCF over the eq. 7.6 width
    bool minMaxHierarchy = false;   // skip the taps the map's min/max hierarchy proves (same bits)
    RotationNoise rotation = RotationNoise::Hash;   // what turns both disks per pixel (pcf.h)
};

// resolution, search-taps, search-region, filter-taps, min-max-hierarchy, rotation.
const SettingsTable<PcssSettings>& pcssSettingsTable();

// The map of the light's centre, its view wide enough for every receiver's blocker search.
const SoftShadowMap& renderPcssMap(const ShadowInputs& in, int resolution);

struct PcssBuffers {
    std::vector<float> visibility;
    std::vector<float> blockerDistance;   // d_o, m from the light's centre; 0 where no blocker was found
    std::vector<float> widthTexels;       // the eq. 7.6 filter width
    // With the hierarchy: per pixel, the taps whose answer it proved (else empty), and the
    // share of the taps a per-pixel PCSS takes that they are, percent.
    std::vector<float> knownTaps;
    double knownTapsPercent = 0.0;
};

// The map's min/max hierarchy (min_max_hierarchy.h) where settings.minMaxHierarchy asks
// for it, else none.
std::optional<MinMaxHierarchy> pcssHierarchy(const SoftShadowMap& soft, const PcssSettings& settings);

// The three steps per camera pixel; where the light's centre cannot reach a pixel, V = 0.
// With a hierarchy, the taps whose answers it proves are skipped (the same bits).
PcssBuffers pcssPerPixel(const ShadowInputs& in, const SoftShadowMap& soft, const PcssSettings& settings,
                         const std::optional<MinMaxHierarchy>& hierarchy);

}  // namespace shadowlab
