// The shadow-casting lights (DeCoro and Rusinkiewicz 2008, section 2, step 1): the scene's
// environment sampled into N distant lights, each carrying the integral of its region of
// the map, so that together they hold all of the map's light. N is the paper's illumination
// detail (section 2.2). Two samplers: median cut (Debevec 2005; median_cut.h), regions of
// about equal energy, and structured importance sampling (Agarwal et al. 2003, the paper's;
// structured_sampling.h), strata of luminance sampled by importance and spread evenly.
#pragma once

#include <cstdint>
#include <vector>

#include "scenes/prepared_scene.h"
#include "scenes/scene.h"
#include "shading/environment/median_cut.h"
#include "shadows/settings_table.h"
#include "shadows/technique.h"

namespace shadowlab {

enum class LightSampler { MedianCut, Structured };

struct LightSamplingSettings {
    int count = 40;   // N
    LightSampler sampler = LightSampler::MedianCut;
};

// The parameters `lights` (N) and `sampler`.
const SettingsTable<LightSamplingSettings>& lightSamplingSettingsTable();

// The N lights from the scene's map (structured sampling works on its pyramid, built once
// per scene). `regionOfTexel`, if given, receives each map texel's light (drawing the
// regions, environment_debug.h).
std::vector<EnvironmentLight> sampleLights(const PreparedScene& prepared, const LightSamplingSettings& settings,
                                           std::vector<uint32_t>* regionOfTexel = nullptr);

// Technique::prepare's part for the sampling: the map (`environment_ms`) and, for
// structured sampling, its pyramid (`environment_pyramid_ms`), each built once per scene.
std::vector<TechniqueStat> prepareLightSampling(const PreparedScene& prepared, const LightSamplingSettings& settings);

// The light as the shadow techniques see it: directional, towards the region's centroid,
// its irradiance at normal incidence the region's power.
Light directionalLight(const EnvironmentLight& light);

}  // namespace shadowlab
