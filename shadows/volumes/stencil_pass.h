// The hard shadow of a point (or an area light's centre) counted in the stencil buffer:
// steps 1 to 5 of `shadow-volume` (shadow_volume.cpp describes them), callable by any
// technique that needs the count per pixel: `shadow-volume` itself, and the soft shadow
// volumes (shadows/wedges/), whose hard shadow of the light's centre it is.
#pragma once

#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "raster/rasterizer.h"
#include "shadows/settings_table.h"
#include "shadows/stage_timer.h"
#include "shadows/technique.h"
#include "shadows/volumes/volume_extrusion.h"

namespace shadowlab {

enum class VolumeCounting { ZPass, ZFail };
enum class VolumeMode { Auto, ZPass, ZFail };   // the `mode` parameter: a counting, or auto

// What the volume does with a cut-out (a foliage card), whose alpha texture a volume of
// whole triangles cannot follow (the `cut-outs` parameter; docs/cut-outs.md): cast the
// whole triangles when at least half the texture's texels are solid and nothing otherwise,
// whichever misclassifies less of its shadow if the texture is mapped once over the mesh;
// always cast them; never.
enum class CutOutVolumes { Coverage, Solid, None };

struct StencilPassSettings {
    VolumeMode mode = VolumeMode::Auto;
    float offsetUnits = 0.0f;   // polygon offset of the volume faces, in depth buffer steps
    CutOutVolumes cutOuts = CutOutVolumes::Coverage;
};

// The parameters of the pass: `mode`, `offset` and `cut-outs`.
const SettingsTable<StencilPassSettings>& stencilPassSettingsTable();

struct StencilPass {
    VolumeCounting counting = VolumeCounting::ZPass;
    bool nearPlaneShadowed = false;   // what auto decides by (counting_mode.h)
    ShadowVolume volume;
    glm::mat4 clipFromWorld{1.0f};    // the camera's infinite-far projection the pass drew with
    raster::RasterStats fill;         // the stencil pass's figures; fragments are the fill
    float offsetUnits = 0.0f;         // the settings' offset, which listSideFragments draws with too
};

// Extrudes the casters' volume for `light` (laps "extrusion" on the timer), then draws the
// receivers' depth with the camera's infinite-far projection (clipFromWorldInfinite) and
// the volume into the stencil of `fb` (laps "stencil"). `fb` must have a stencil buffer;
// afterwards it holds that depth and the count per pixel, modulo 256.
StencilPass runStencilPass(raster::Rasterizer& rasterizer, raster::Framebuffer& fb, const ShadowInputs& in,
                           const StencilPassSettings& settings, const glm::dvec4& light, StageTimer& timer);

// Lists, per tile, the fragments of the volume sides of the given silhouette edges
// (indices into pass.volume.silhouette) that pass the stencil pass's own depth test, i.e.
// the pixels where the pass counted the side as in front of the receiver; each fragment's
// primitive id is its edge. The same vertices, matrix and offset as the pass, so the same
// bits decide. `fb` must have a fragment list; it is cleared first.
void listSideFragments(raster::Rasterizer& rasterizer, raster::Framebuffer& fb, const StencilPass& pass,
                       std::span<const uint32_t> edges);

// The fill per pixel (fragments of the volume faces at each pixel), for debug views; needs
// a colour buffer and leaves colour plane 0 holding it.
std::vector<float> fillPerPixel(raster::Rasterizer& rasterizer, raster::Framebuffer& fb, const StencilPass& pass);

// The pass's figures: counting, open and non-manifold edges, silhouette, volume triangles, fill.
void appendStencilPassStats(const ShadowInputs& in, const StencilPass& pass, std::vector<TechniqueStat>& stats);

}  // namespace shadowlab
