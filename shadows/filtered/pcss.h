// Percentage-closer soft shadows as a pass (pcss.cpp): the `pcss` technique runs it, and so
// does the hybrid izb-pcss (shadows/hybrid), which also reads the blocker distance it finds
// per pixel to choose between the hard and the soft shadow.
#pragma once

#include <vector>

#include "shadows/filtered/blocker_search.h"
#include "shadows/filtered/soft_shadow_map.h"
#include "shadows/technique.h"

namespace shadowlab {

struct PcssSettings {
    int resolution = 1024;          // texels per side of the map
    BlockerSearchSettings search;
    int filterTaps = 32;            // Poisson taps of the PCF over the eq. 7.6 width
};

// resolution, search-taps, search-region, filter-taps.
std::vector<ParamSpec> pcssParamSpecs();
PcssSettings readPcssSettings(const TechniqueParams& params);

// The map of the light's centre, its view wide enough for every receiver's blocker search.
SoftShadowMap renderPcssMap(const ShadowInputs& in, int resolution);

struct PcssBuffers {
    std::vector<float> visibility;
    std::vector<float> blockerDistance;   // d_o, m from the light's centre; 0 where no blocker was found
    std::vector<float> widthTexels;       // the eq. 7.6 filter width
};

// The three steps per camera pixel; where the light's centre cannot reach a pixel, V = 0.
PcssBuffers pcssPerPixel(const ShadowInputs& in, const SoftShadowMap& soft, const PcssSettings& settings);

}  // namespace shadowlab
