// The first two steps of percentage-closer soft shadows (Fernando 2005, "Percentage-Closer
// Soft Shadows", SIGGRAPH sketch, steps 1 and 2; Real-Time Rendering, 4th ed., 7.6):
//
//   1. blocker search: the map texels inside the light's cone from the receiver, cut at the
//      near plane (soft_shadow_map.h), are tested with a rotated Poisson disk of taps;
//      those nearer the light than the receiver are blockers, and their mean distance
//      from the light is d_o. No blocker: the receiver is fully lit and step 3 is skipped.
//   2. penumbra estimate: eq. 7.6, w_sample = w_light (d_r - d_o) / d_r, in map texels.
//
// Step 3 (pcss.cpp: PCF; filtered_shadow_map.cpp: a summed-area-table box) filters over
// that width. The taps compare against the receiver's plane (receiver-plane depth bias,
// RTR 7.5, Figure 7.24 middle), since a search region many texels wide on a slanted
// receiver would otherwise find the receiver itself. Both steps run in float in the shadow
// lookup's vector kernel (shadows/maps/lookup_kernel.inl: searchDisk, eq. 7.6 in
// penumbraTexels); here are their settings and the receiver's plane for the double passes.
#pragma once

#include <glm/glm.hpp>

#include "shadows/filtered/soft_shadow_map.h"
#include "shadows/maps/shadow_bias.h"
#include "shadows/settings_table.h"

namespace shadowlab {

struct BlockerSearchSettings {
    int taps = 16;                  // Poisson taps of the search
    double region = 1.0;            // fraction of Fernando's region (the full light cone)
};

// search-taps, search-region: rows the techniques with a blocker search include.
const SettingsTable<BlockerSearchSettings>& blockerSearchSettingsTable();

// The receiver as the blocker search and PCF compare it: on its own plane.
MapReceiver planeReceiver(const SoftShadowMap& soft, const glm::dvec3& P, const glm::dvec3& N);

}  // namespace shadowlab
