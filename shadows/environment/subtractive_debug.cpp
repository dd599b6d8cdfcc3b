#include "shadows/environment/subtractive_debug.h"

#include <numbers>

#include "shading/environment/environment_debug.h"

namespace shadowlab {

void writeSubtractiveDebug(const DebugBuffers& debug, const ShadowInputs& in, const EnvironmentMap& map,
                           const SampledLightsView& lights, const SubtractiveBuffers& buffers) {
    if (!debug.enabled()) return;
    const GBuffer& g = in.gbuffer;
    debug.writeRadiance("C", g.width, g.height, buffers.C);
    debug.writeRadiance("S", buffers.sampled.width, buffers.sampled.height, buffers.S);
    debug.writeRadiance("S-resampled", g.width, g.height, buffers.resampled);
    debug.writePicture("lights", map.width, map.height, lightsImage(map, lights.lights, lights.regionOfTexel, {}));
    debug.writeRadiance("sh-radiance", map.width, map.height, shImage(map, projectRadiance(map)));
    debug.writeRadiance("sh-irradiance", map.width, map.height, shImage(map, irradianceOf(projectRadiance(map)), std::numbers::inv_pi));
}

}  // namespace shadowlab
