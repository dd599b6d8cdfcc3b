#include "shadows/denoise/tiled.h"

#include <stdexcept>
#include <string>
#include <utility>

#include "shadows/denoise/atrous_pass.h"
#include "shadows/denoise/surface_features.h"
#include "shadows/denoise/tile_classification.h"

namespace shadowlab {

TiledResult denoiseTiled(const DenoiseInputs& in, const TiledSettings& s, const MomentsHistory& before,
                         MomentsHistory& after, const DebugBuffers* debug) {
    if (s.passes < 1 || s.passes > 10) throw std::invalid_argument("tiled denoiser: passes must be in 1..10");
    checkDenoiseInputs(in, false);
    const GBuffer& g = in.gbuffer;
    accumulateMoments(in.visibility, g, in.reprojection, before, s.moments, after);
    const TileClasses classes = classifyTiles(in.visibility, after.signal.value, g, s.tileSize);
    const std::vector<uint8_t> filtered = classes.filteredPixels(g);
    const SurfaceFeatures features = surfaceFeatures(g, in.view);
    FilteredSignal signal{after.signal.value,
                          estimateVariance(in.visibility, g, features, after, s.edges, s.variance)};
    const bool show = debug && debug->enabled();
    if (show) {
        debug->write("tiled-accumulated", g.width, g.height, signal.value, 0.0f, 1.0f);
        debug->write("tiled-variance", g.width, g.height, signal.variance, 0.0f, 0.25f);
        debug->write("tiled-classes", g.width, g.height, classes.classImage(g), 0.0f, 3.0f);
    }
    FilteredSignal next;
    for (int pass = 1; pass <= s.passes; ++pass) {
        atrousPass(signal, g, features, s.edges, 1 << (pass - 1), filtered, next);
        std::swap(signal, next);
        if (show) debug->write("tiled-pass-" + std::to_string(pass), g.width, g.height, signal.value, 0.0f, 1.0f);
    }
    for (size_t k = 0; k < g.pixelCount(); ++k)
        if (!g.hit[k]) signal.value[k] = in.visibility[k];
    return {std::move(signal.value), classes.skipped, classes.surfaced};
}

}  // namespace shadowlab
