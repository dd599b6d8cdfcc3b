#include "shadows/temporal/confidence_reprojection.h"

#include <utility>

#include "shadows/debug_buffers.h"
#include "shadows/depth_map.h"
#include "shadows/kept_raster.h"
#include "shadows/light_view.h"
#include "shadows/maps/shadow_lookup.h"
#include "shadows/stage_timer.h"
#include "shadows/temporal/confidence_blend.h"
#include "shadows/temporal/shadow_test_confidence.h"

namespace shadowlab {
namespace {

// What the technique keeps between frames: its map's memory and the last frame's result.
struct ConfidenceHistory {
    DepthMap map;
    KeptRasterizer rasterizer;
    std::vector<float> last, next;
};

// The radical inverse of `index` in `base`: the Halton sequence's coordinate.
double radicalInverse(uint64_t index, uint64_t base) {
    double result = 0.0, digit = 1.0 / double(base);
    for (; index > 0; index /= base, digit /= double(base)) result += double(index % base) * digit;
    return result;
}

// The light's view with its texel grid shifted by `texels` (in [-0.5, 0.5) per axis): a
// translation of clip space by 2 texels / resolution, the same for an orthographic and a
// perspective view (x_clip += t w).
LightView jittered(LightView view, const glm::dvec2& texels, int resolution) {
    glm::dmat4 shift(1.0);
    shift[3][0] = 2.0 * texels.x / resolution, shift[3][1] = 2.0 * texels.y / resolution;
    view.clipFromView = shift * view.clipFromView;
    return view;
}

// Frame f's offset, Halton(2, 3) from index 1 (index 0 is the origin of both axes).
glm::dvec2 frameJitter(uint64_t frame) {
    return {radicalInverse(frame + 1, 2) - 0.5, radicalInverse(frame + 1, 3) - 0.5};
}

ShadowOutputs run(const ShadowInputs& in) {
    const ConfidenceReprojectionSettings s = confidenceReprojectionSettingsTable().read(in.params);
    ConfidenceHistory& history = in.kept().state<ConfidenceHistory>();
    if (!anyReachable(in.gbuffer, in.light)) {
        ShadowOutputs unlit = unlitOutputs(in.gbuffer);
        history.last = unlit.visibility;   // this frame's result: the next frame reprojects it, not an older one
        return unlit;
    }
    StageTimer timer;
    const Light light = pointLightFor(in.light);
    LightFitOptions fit;
    fit.resolution = s.map.resolution;
    // shadow-map's margin, and the jitter's half texel.
    fit.marginTexels = kernelRadiusTexels(s.map.filter) + 1.5 + (s.jitter ? 0.5 : 0.0);
    fit.simd = in.simd;
    fit.scratch = &in.kept().state<LightViewScratch>();
    const glm::dvec2 offset = s.jitter ? frameJitter(in.frameIndex) : glm::dvec2(0.0);
    const LightView view = jittered(fitLightView(light, in.gbuffer, in.casterWorld(), fit), offset, s.map.resolution);
    timer.lap("light_view");
    history.map = renderDepthMap(in.casters(), view, depthMapSettings(s.map), in.simd, std::move(history.map),
                                 &history.rasterizer.at(in.simd));
    timer.lap("depth_map");
    const ShadowLookup tests = lookUpShadows(in.gbuffer, in.camera(), light, std::span(&history.map, 1), OneMap{},
                                             s.map.bias, makePcfKernel(s.map.filter, in.frameIndex), in.simd);
    timer.lap("lookup");
    const std::vector<float> confidence = shadowTestConfidence(in.gbuffer, history.map, light, s.map.bias);
    timer.lap("confidence");
    const std::optional<Reprojection> reprojection =
        reprojectHistory(in.gbuffer, in.previous, history.last.size(), s.reprojection);
    blendByConfidence(tests.visibility, confidence, s.exponent, in.gbuffer, reprojection ? &*reprojection : nullptr,
                      history.last, history.next);
    std::swap(history.last, history.next);
    timer.lap("history");
    const DebugBuffers debug(in.debugDir, "confidence-reprojection");
    const int w = in.gbuffer.width, h = in.gbuffer.height;
    debug.write("test", w, h, tests.visibility, 0.0f, 1.0f);
    debug.write("confidence", w, h, confidence, 0.0f, 1.0f);
    ShadowOutputs out;
    out.visibility = history.last;
    out.stats = {{"resolution_texels", double(s.map.resolution)},
                 {"jitter_x_texels", offset.x},
                 {"jitter_y_texels", offset.y},
                 {"history_rejected_pixels", reprojection ? double(reprojection->rejectedPixels) : 0.0}};
    timer.appendTo(out.stats);
    return out;
}

}  // namespace

const SettingsTable<ConfidenceReprojectionSettings>& confidenceReprojectionSettingsTable() {
    using S = ConfidenceReprojectionSettings;
    static const auto table = SettingsTable<S>()
                                  .include(member(&S::map), shadowMapSettingsTable())
                                  .real("confidence-exponent", member(&S::exponent), 0.0, 64.0,
                                        "m: a frame's test weighs c^m in the history (Scherzer et al. 2007)")
                                  .flag("jitter", member(&S::jitter), "shift the map by a sub-texel offset every frame");
    return table;
}

Technique confidenceReprojectionTechnique() {
    return {.name = "confidence-reprojection",
            .description = "pixel-correct shadow maps (Scherzer et al. 2007): a jittered map each frame, its test "
                           "blended into the reprojected history by its confidence",
            .params = confidenceReprojectionSettingsTable().specs(),
            .run = run,
            .temporal = true};
}

}  // namespace shadowlab
