#include "shadows/raytraced/ray_denoising.h"

#include <cmath>
#include <numbers>
#include <utility>

#include "raster/portable_math.h"
#include "shadows/debug_buffers.h"
#include "shadows/denoise/penumbra.h"
#include "shadows/denoise/svgf.h"
#include "shadows/denoise/tiled.h"

namespace shadowlab {

DenoiseLight denoiseLightOf(const Light& light) {
    DenoiseLight out;
    out.position = light.position;
    switch (light.type) {
        case LightType::Disk: out.radius = light.radius; break;
        case LightType::Rectangle:
            out.radius = float(std::sqrt(4.0 * glm::length(glm::dvec3(light.halfEdgeU)) *
                                         glm::length(glm::dvec3(light.halfEdgeV)) / std::numbers::pi));
            break;
        case LightType::Directional:
            out.directional = true;
            out.tanAngularRadius = float(portable::tan(glm::radians(double(light.angularDiameterDeg)) / 2.0));
            break;
        case LightType::Point:
        case LightType::Spot: break;
    }
    return out;
}

DenoisedRays denoiseRays(const ShadowInputs& in, ShadowDenoiser which, const ShadowRayBuffers& rays,
                         DenoiserHistory& history) {
    const Camera& camera = in.camera();
    const DenoiseView view{camera.eye, float(camera.height / (2.0 * portable::tan(glm::radians(double(camera.fovyDeg)) / 2.0)))};
    const size_t lastSize = which == ShadowDenoiser::Penumbra ? history.stabilised.value.size()
                                                              : history.moments.signal.value.size();
    const std::optional<Reprojection> reprojection = reprojectHistory(in.gbuffer, in.previous, lastSize, {});
    const DenoiseInputs inputs{in.gbuffer, rays.visibility, rays.occluderDistance, view, denoiseLightOf(in.light),
                               reprojection ? &*reprojection : nullptr};
    const DebugBuffers debug(in.debugDir, "ray-traced");
    const DebugBuffers* shown = debug.enabled() ? &debug : nullptr;
    DenoisedRays out;
    switch (which) {
        case ShadowDenoiser::Svgf:
            out.visibility = denoiseSvgf(inputs, {}, history.moments, history.nextMoments, shown);
            std::swap(history.moments, history.nextMoments);
            break;
        case ShadowDenoiser::Tiled: {
            TiledResult tiled = denoiseTiled(inputs, {}, history.moments, history.nextMoments, shown);
            std::swap(history.moments, history.nextMoments);
            out.visibility = std::move(tiled.visibility);
            out.skippedTilesShare = tiled.skippedShare();
            break;
        }
        case ShadowDenoiser::Penumbra:
            out.visibility = denoisePenumbra(inputs, {}, history.stabilised, history.nextStabilised, shown);
            std::swap(history.stabilised, history.nextStabilised);
            break;
        case ShadowDenoiser::None: out.visibility = rays.visibility; break;
    }
    return out;
}

}  // namespace shadowlab
