#include "shadows/denoise/svgf.h"

#include <stdexcept>
#include <string>
#include <utility>

#include "shadows/denoise/atrous_pass.h"
#include "shadows/denoise/surface_features.h"

namespace shadowlab {

std::vector<float> denoiseSvgf(const DenoiseInputs& in, const SvgfSettings& s, const MomentsHistory& before,
                               MomentsHistory& after, const DebugBuffers* debug) {
    if (s.passes < 1 || s.passes > 10 || s.feedbackPass < 1 || s.feedbackPass > s.passes)
        throw std::invalid_argument("svgf: passes must be in 1..10 and the feedback pass in 1..passes");
    checkDenoiseInputs(in, false);
    const GBuffer& g = in.gbuffer;
    const SurfaceFeatures features = surfaceFeatures(g, in.view);
    accumulateMoments(in.visibility, g, in.reprojection, before, s.moments, after);
    FilteredSignal signal{after.signal.value,
                          estimateVariance(in.visibility, g, features, after, s.edges, s.variance)};
    const bool show = debug && debug->enabled();
    if (show) {
        debug->write("svgf-accumulated", g.width, g.height, signal.value, 0.0f, 1.0f);
        debug->write("svgf-variance", g.width, g.height, signal.variance, 0.0f, 0.25f);
    }
    FilteredSignal next;
    for (int pass = 1; pass <= s.passes; ++pass) {
        atrousPass(signal, g, features, s.edges, 1 << (pass - 1), {}, next);
        std::swap(signal, next);
        if (pass == s.feedbackPass) after.signal.value = signal.value;
        if (show) {
            debug->write("svgf-pass-" + std::to_string(pass), g.width, g.height, signal.value, 0.0f, 1.0f);
            debug->write("svgf-pass-" + std::to_string(pass) + "-variance", g.width, g.height, signal.variance, 0.0f,
                         0.25f);
        }
    }
    for (size_t k = 0; k < g.pixelCount(); ++k)
        if (!g.hit[k]) signal.value[k] = in.visibility[k];
    return std::move(signal.value);
}

}  // namespace shadowlab
