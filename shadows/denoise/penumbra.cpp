#include "shadows/denoise/penumbra.h"

#include "shadows/denoise/penumbra_filter.h"
#include "shadows/denoise/surface_features.h"

namespace shadowlab {

std::vector<float> denoisePenumbra(const DenoiseInputs& in, const PenumbraSettings& s, const AccumulatedFrame& before,
                                   AccumulatedFrame& after, const DebugBuffers* debug) {
    checkDenoiseInputs(in, true);
    const GBuffer& g = in.gbuffer;
    const SurfaceFeatures features = surfaceFeatures(g, in.view);
    const std::vector<float> radius = penumbraRadius(in, features, s.radius);
    const std::vector<float> spatial = penumbraFilter(in.visibility, g, features, radius, s.edges, s.taps);
    accumulate(spatial, g, in.reprojection, before, s.stabilisation, after);
    if (debug && debug->enabled()) {
        debug->write("penumbra-radius", g.width, g.height, radius, 0.0f, s.radius.maxRadius);
        debug->write("penumbra-spatial", g.width, g.height, spatial, 0.0f, 1.0f);
        debug->write("penumbra-frames", g.width, g.height, after.frames, 0.0f, float(s.stabilisation.maxFrames));
    }
    std::vector<float> out = after.value;
    for (size_t k = 0; k < g.pixelCount(); ++k)
        if (!g.hit[k]) out[k] = in.visibility[k];
    return out;
}

}  // namespace shadowlab
