// The passes over many lights that the environment techniques share: for each light, its V
// by the technique's visibility method (light_visibility.h), then its share of the reflected
// light added where it is lit or where it is occluded (light_contribution.h).
//
//   sampled lights  the N lights sampled from the environment (environment_lights.h), each
//                   shaded with its lobe as a point or widened by its region (light_lobes.h),
//                   on any G-buffer of the view (subtractive shadows use a smaller one);
//   scene lights    the scene's own lights (point, spot, directional, area), added on top of
//                   the environment's light at full resolution (DeCoro and Rusinkiewicz 2008,
//                   section 4).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "shading/environment/median_cut.h"
#include "shadows/environment/environment_lights.h"
#include "shadows/environment/light_contribution.h"
#include "shadows/environment/light_lobes.h"
#include "shadows/environment/light_visibility.h"
#include "shadows/settings_table.h"
#include "shadows/stage_timer.h"
#include "shadows/technique.h"

namespace shadowlab {

// The settings of the sampled lights' passes, which the additive and subtractive techniques share.
struct SampledLightSettings {
    LightSamplingSettings sampling;           // `lights`, `sampler`
    LightLobes lobes = LightLobes::Point;     // `light-lobes`
    LightVisibilitySettings visibility;       // `visibility`, `resolution`
};

const SettingsTable<SampledLightSettings>& sampledLightSettingsTable();

// Technique::prepare's part: the sampling's and the visibility's.
std::vector<TechniqueStat> prepareSampledLights(const PreparedScene& prepared, const PreparedScene& casters,
                                                const SampledLightSettings& settings);

// Adds every sampled light's `part` to `sum` (one entry per pixel of g, the view seen by
// `camera`); returns the pixels shaded. Times the stages `visibility` and, for the lit part,
// `shading`, for the occluded part `shadow_buffer`.
uint64_t addSampledLights(const ShadowInputs& in, LightVisibility& visibility, const std::vector<EnvironmentLight>& lights,
                          LightLobes lobes, const GBuffer& g, const Camera& camera, LightPart part,
                          std::vector<glm::vec3>& sum, StageTimer& timer);

// Adds every light of in.scene() to `radiance` (one entry per pixel of in.gbuffer); returns
// the pixels shaded.
uint64_t addSceneLights(const ShadowInputs& in, LightVisibility& visibility, std::vector<glm::vec3>& radiance);

}  // namespace shadowlab
