#include "shadows/projected/projected_texture.h"

#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "shadows/debug_buffers.h"
#include "shadows/kept_raster.h"
#include "shadows/projected/instance_roles.h"
#include "shadows/projected/occluder_texture.h"
#include "shadows/projected/texture_projection.h"
#include "shadows/settings_table.h"
#include "shadows/stage_timer.h"

namespace shadowlab {
namespace {

struct ProjectedTextureSettings {
    std::optional<std::vector<std::string>> occluders;   // auto: every instance not a receiver
    std::optional<std::vector<std::string>> receivers;   // auto: chooseRoles decides
    int resolution = 1024;
};

const SettingsTable<ProjectedTextureSettings>& projectedTextureSettingsTable() {
    using S = ProjectedTextureSettings;
    static const auto table =
        SettingsTable<S>()
            .names("occluders", member(&S::occluders),
                   "instances drawn into the texture; auto: every one not a receiver")
            .names("receivers", member(&S::receivers),
                   "instances the texture is projected onto; auto: those named ground, else the largest by area")
            .include(member(&S::resolution), mapResolutionTable("texels per side of the occluders' texture"));
    return table;
}

// The occluder texture and the rasterizer that draws it, kept between frames
// (technique_history.h, kept_raster.h).
struct KeptTexture {
    OccluderTexture texture;
    KeptRasterizer rasterizer;
};

ShadowOutputs runProjectedTexture(const ShadowInputs& in) {
    const ProjectedTextureSettings settings = projectedTextureSettingsTable().read(in.params);
    const Light light = pointLightFor(in.light);
    const int resolution = settings.resolution;
    // Both roles are chosen on the scene the camera sees; the casters' copy (a caster level
    // of detail) has the same instances, so its triangles take the same roles.
    const InstanceRoles roles = chooseRoles(in.scene(), in.receiverWorld(), settings.occluders, settings.receivers);
    if (!anyReachable(in.gbuffer, in.light)) return unlitOutputs(in.gbuffer);   // settings checked first
    StageTimer timer;
    const std::vector<uint32_t> occluders = trianglesWithRole(in.casterWorld(), roles.occluder);
    timer.lap("roles");
    KeptTexture& kept = in.kept().state<KeptTexture>();   // last frame's, its memory reused
    kept.texture = renderOccluderTexture(in.casterWorld(), occluders, light, resolution, in.simd, std::move(kept.texture),
                                         &kept.rasterizer.at(in.simd));
    const OccluderTexture& texture = kept.texture;
    timer.lap("texture");
    ProjectedShadow shadow = projectOntoReceivers(in.gbuffer, in.receiverWorld(), roles.receiver, light, texture);
    timer.lap("projection");

    ShadowOutputs out;
    out.stats = {{"resolution_texels", double(resolution)},
                 {"occluder_triangles", double(occluders.size())},
                 {"receiver_pixels", double(shadow.receiverPixels)},
                 {"shadowed_receiver_pixels", double(shadow.shadowedPixels)}};
    timer.appendTo(out.stats);
    const DebugBuffers debug(in.debugDir, "projected-texture");
    if (debug.enabled()) {
        if (!texture.empty()) debug.write("texture", resolution, resolution, texture.image(), 0.0f, 1.0f);
        debug.write("receivers", in.gbuffer.width, in.gbuffer.height, shadow.receiverMask, 0.0f, 1.0f);
    }
    out.visibility = std::move(shadow.visibility);
    return out;
}

}  // namespace

Technique projectedTextureTechnique() {
    return {.name = "projected-texture",
            .description = "projected shadow texture (RTR 7.2): the occluders' image from the light projected onto "
                           "chosen receivers (no self-shadows, shadows cast backward)",
            .params = projectedTextureSettingsTable().specs(),
            .run = runProjectedTexture,
            .referenceName = "reference",
            .output = TechniqueOutput::Visibility};
}

}  // namespace shadowlab
