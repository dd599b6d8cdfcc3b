// The `confidence-reprojection` technique: pixel-correct shadow maps with temporal
// reprojection and shadow test confidence (Scherzer, Jeschke and Wimmer 2007). Each frame
// draws one shadow map, its grid shifted by a sub-texel offset (Halton(2, 3), as TAA
// jitters a camera), tests every pixel as `shadow-map` does, and blends the test into the
// pixel's reprojected history at the weight of its confidence (shadow_test_confidence.h,
// confidence_blend.h). On a still view the shadow's staircase sharpens over the frames
// towards the exact edge, the paper's "pixel-correct" shadow. A frame alone is the jittered
// map's plain test.
#pragma once

#include "shadows/maps/shadow_map_settings.h"
#include "shadows/settings_table.h"
#include "shadows/technique.h"
#include "shadows/temporal/reprojection.h"

namespace shadowlab {

struct ConfidenceReprojectionSettings {
    ShadowMapSettings map;
    double exponent = 4.0;   // m: the test's weight is c^m
    bool jitter = true;      // shift the map's grid by a sub-texel offset every frame
    ReprojectionSettings reprojection;
};
const SettingsTable<ConfidenceReprojectionSettings>& confidenceReprojectionSettingsTable();

Technique confidenceReprojectionTechnique();

}  // namespace shadowlab
