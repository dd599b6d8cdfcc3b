// The buffers of subtractive shadows on request (`--debug-buffers DIR`; the paper's
// Figure 2): C, the unshadowed light; S, the occluded light at the sampling detail's size;
// S', S resampled to full size; the N lights drawn on the environment map; and the map's
// nine-term SH reconstruction and the irradiance it gives a white Lambert surface (as
// latitude-longitude images).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "shading/environment/median_cut.h"
#include "shading/gbuffer.h"
#include "shadows/debug_buffers.h"
#include "shadows/technique.h"

namespace shadowlab {

struct SubtractiveBuffers {
    const std::vector<glm::vec3>& C;
    const std::vector<glm::vec3>& S;
    const GBuffer& sampled;             // the G-buffer S was computed on
    const std::vector<glm::vec3>& resampled;
};

struct SampledLightsView {
    const std::vector<EnvironmentLight>& lights;
    const std::vector<uint32_t>& regionOfTexel;   // sampleLights()'s
};

void writeSubtractiveDebug(const DebugBuffers& debug, const ShadowInputs& in, const EnvironmentMap& map,
                           const SampledLightsView& lights, const SubtractiveBuffers& buffers);

}  // namespace shadowlab
