#include "shadows/raytraced/ray_traced.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "shadows/debug_buffers.h"
#include "shadows/raytraced/ray_denoising.h"
#include "shadows/raytraced/shadow_rays.h"
#include "shadows/reference/scene_rays.h"
#include "shadows/settings_table.h"
#include "shadows/stage_timer.h"

namespace shadowlab {
namespace {

struct RayTracedSettings {
    int rays = 1;
    ShadowDenoiser denoiser = ShadowDenoiser::None;
};

const SettingsTable<RayTracedSettings>& rayTracedSettingsTable() {
    using S = RayTracedSettings;
    static const auto table =
        SettingsTable<S>()
            .integer("rays", member(&S::rays), 1, 1024,
                     "N: rays per pixel (towards an area light or a sun with a size, N samples of its area, new "
                     "each frame)")
            .choice("denoiser", member(&S::denoiser),
                    {{"none", ShadowDenoiser::None},
                     {"svgf", ShadowDenoiser::Svgf, "spatiotemporal variance-guided filtering (Schied et al. 2017)"},
                     {"tiled", ShadowDenoiser::Tiled, "tile-classified, after AMD FidelityFX's shadow denoiser"},
                     {"penumbra", ShadowDenoiser::Penumbra, "penumbra-driven, after NVIDIA SIGMA's inputs"}},
                    "the filter the noisy V goes through (docs/denoisers.md)");
    return table;
}

void writeRayBuffers(const ShadowInputs& in, const ShadowRayBuffers& buffers, int raysPerPixel) {
    const DebugBuffers debug(in.debugDir, "ray-traced");
    if (!debug.enabled()) return;
    const int w = in.gbuffer.width, h = in.gbuffer.height;
    const auto farthest = std::ranges::max_element(buffers.occluderDistance);
    debug.write("visibility", w, h, buffers.visibility, 0.0f, 1.0f);
    debug.write("occluder-distance", w, h, buffers.occluderDistance, 0.0f, std::max(*farthest, 1e-6f));
    std::vector<float> occluded(buffers.occludedRays.begin(), buffers.occludedRays.end());
    debug.write("occluded-rays", w, h, occluded, 0.0f, float(raysPerPixel));
}

ShadowOutputs rayTraced(const ShadowInputs& in) {
    const RayTracedSettings settings = rayTracedSettingsTable().read(in.params);
    // The frame's place in its sequence (0 for a frame alone) moves the samples on.
    const uint32_t frame = uint32_t(in.frameIndex);
    StageTimer timer;
    const ReferenceVisibility& rays = sceneRays(in.casters());   // built by the first frame, then kept
    timer.lap("bvh");
    ShadowRayBuffers buffers = traceShadowRays(rays, in.gbuffer, in.light, settings.rays, frame, in.progress);
    timer.lap("rays");
    writeRayBuffers(in, buffers, settings.rays);
    ShadowOutputs out;
    out.stats = {{"rays_per_pixel", double(settings.rays)},
                 {"rays_cast_count", double(buffers.raysCast)},
                 {"frame_count", double(frame)}};
    if (settings.denoiser != ShadowDenoiser::None) {
        if (!buffers.coloured.empty())
            throw std::invalid_argument("ray-traced: denoising tinted casters' coloured V is not built; give denoiser=none");
        DenoisedRays denoised = denoiseRays(in, settings.denoiser, buffers, in.kept().state<DenoiserHistory>());
        timer.lap("denoise");
        buffers.visibility = std::move(denoised.visibility);
        if (denoised.skippedTilesShare) out.stats.push_back({"denoise_skipped_tiles_percent", 100.0 * *denoised.skippedTilesShare});
    }
    timer.appendTo(out.stats);
    out.visibility = std::move(buffers.visibility);
    out.colouredVisibility = std::move(buffers.coloured);
    return out;
}

}  // namespace

Technique rayTracedTechnique() {
    return {.name = "ray-traced",
            .description = "N Embree rays per pixel towards the light, area samples new each frame, "
                           "with the distance to the first occluder (the noisy input of denoisers)",
            .params = rayTracedSettingsTable().specs(),
            .run = rayTraced,
            .referenceName = "reference-soft",
            .output = TechniqueOutput::Visibility,
            .temporal = true};
}

}  // namespace shadowlab
