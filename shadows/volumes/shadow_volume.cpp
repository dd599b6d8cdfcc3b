// `shadow-volume`: exact hard shadows by counting shadow-volume crossings in the stencil
// buffer (Crow 1977; Heidmann 1991; Everitt and Kilgard 2002, "Practical and Robust
// Stenciled Shadow Volumes"; RTR 4th ed., section 7.3). Per frame:
//
//   1. edge adjacency per mesh (scenes/edge_adjacency.h; built once per prepared scene,
//      as an engine builds it at load time), silhouette edges per instance w.r.t. the
//      light (silhouette.h), sides extruded to infinity with w = 0 and, for z-fail, light
//      and dark caps (volume_extrusion.h);
//   2. z-pass or z-fail: param mode, or `auto`, which takes z-fail exactly when a volume
//      may reach the near-plane rectangle (counting_mode.h);
//   3. a depth prepass of the scene with the camera's infinite-far projection
//      (infinite_projection.h), the same projection the volumes are drawn with;
//   4. one stencil pass, two-sided with wrapping (Everitt and Kilgard, "two-sided
//      stencil"), depth test on and depth writes off, volume faces wound outwards:
//        z-pass: front face, depth pass -> +1; back face, depth pass -> -1
//        z-fail: back face, depth fail  -> +1; front face, depth fail -> -1
//      so the stencil holds, modulo 256, the number of volumes the visible point is in;
//   5. the fill, the technique's known cost (RTR 7.3): the fragments the stencil pass
//      rasterized, counted by the rasterizer and reported as a stat; with debug buffers
//      also per pixel, by a second pass adding 1 per fragment into a colour plane;
//   6. V = 1 where the stencil is 0 and the surface faces the light (the reference's
//      dot(N, L - P) > 0 on the G-buffer's N and P, and its spot cone), else 0.
//
// Self-shadowing of the light-facing surface. A visible light-facing point lies exactly on
// its own light cap: just in front of it the count is 0, just behind it 1. The light cap
// is drawn from the occluder's own vertices with the same matrix, so the rasterizer gives
// it the same depth bits at the pixel as the depth prepass stored there; with the depth
// test `Less`, a fragment at equal depth fails, i.e. it counts as behind the surface.
//   z-fail counts it (front face, depth fail: -1), and the exit behind it (+1): 0, lit.
//   z-pass draws no caps; the face is at the surface and would not count anyway: 0, lit.
// No polygon offset is needed, so none can cut contact shadows short (the light cap's
// index order must match the world's for this, see volume_extrusion.cpp).
//
// Grazing faces. What remains are volume faces that meet a receiver at a shallow angle,
// whose depth differs from the receiver's by less than the float depth buffer resolves.
// Where a face crosses a receiver, the reference has a shadow boundary, so the error stays
// within about a pixel of one. The one other place is a light-facing triangle
// almost edge-on to the light (dot(N, L - P) a few thousandths of |L - P|) next to the
// terminator: its own silhouette sides lie within one depth unit of it, and rounding may
// count one of them. Such a pixel is one pixel from the attached-shadow boundary. Param
// `offset` pushes the volume faces back by that many units of the depth resolution
// (polygon offset): 1 removes those, but shrinks contact shadows where receivers are far
// away (docs/hard-shadows.md gives the counts), so the default is 0.
//
// Back-facing surfaces get V = 0 by the facing test (as in the reference), so the
// terminator of a tessellated object is its polygonal one, as in the reference.
//
// Steps 1 to 5 are the stencil pass (stencil_pass.h), which the soft shadow volumes
// (shadows/wedges/) run for the light's centre; step 6 is here.
#include "shadows/volumes/shadow_volume.h"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include "raster/rasterizer.h"
#include "shading/lights.h"
#include "shadows/debug_buffers.h"
#include "shadows/kept_raster.h"
#include "shadows/silhouettes/silhouette.h"
#include "shadows/silhouettes/silhouette_image.h"
#include "shadows/stage_timer.h"
#include "shadows/volumes/stencil_pass.h"

namespace shadowlab {
namespace {

// Step 6, with the stencil as a signed count per pixel, read in place from the framebuffer
// (Framebuffer::stencil(): block-linear, `tilesX` tiles wide); rows in parallel (the count of
// shadowed pixels is an integer sum, the same in any order).
ShadowOutputs visibilityFromStencil(const GBuffer& g, const Light& light, const uint8_t* stencil, int tilesX) {
    ShadowOutputs out;
    out.visibility.resize(g.pixelCount());
    out.stencil.resize(g.pixelCount());
    const size_t shadowed = tbb::parallel_reduce(
        tbb::blocked_range<int>(0, g.height), size_t(0),
        [&](const tbb::blocked_range<int>& rows, size_t count) {
            for (int j = rows.begin(); j < rows.end(); ++j) {
                for (int x0 = 0; x0 < g.width; x0 += raster::kBlockSize) {
                    // A block's row of pixels is contiguous: one storage index per block.
                    const uint8_t* run = stencil + raster::blockLinearIndex(x0, j, tilesX);
                    for (int i = x0; i < std::min(x0 + raster::kBlockSize, g.width); ++i) {
                        const size_t k = g.index(i, j);
                        const uint8_t s = run[i - x0];
                        out.stencil[k] = float(int8_t(s));   // wrapped count read as signed
                        const bool lit = g.hit[k] && s == 0 && lightReaches(light, g.position[k], g.normal[k]);
                        out.visibility[k] = lit ? 1.0f : 0.0f;
                        count += g.hit[k] && !lit;
                    }
                }
            }
            return count;
        },
        std::plus<>());
    out.stats.push_back({"shadowed_pixels", double(shadowed)});
    return out;
}

// The stencil pass's framebuffer memory and rasterizer, kept between frames (kept_raster.h).
struct StencilBuffers {
    raster::FramebufferStorage memory;
    KeptRasterizer rasterizer;
};

void writeDebug(const DebugBuffers& debug, const ShadowInputs& in, const ShadowOutputs& out, const ShadowVolume& volume,
                const std::vector<float>& fill) {
    const Camera& camera = in.camera();
    debug.write("stencil", camera.width, camera.height, out.stencil, -4.0f, 4.0f);
    debug.write("silhouette", camera.width, camera.height, silhouetteImage(camera, in.casterWorld().positions, volume.silhouette),
                0.0f, 1.0f);
    debug.write("fill", camera.width, camera.height, fill, 0.0f, 8.0f);
}

}  // namespace

ShadowOutputs runShadowVolume(const ShadowInputs& in, const StencilPassSettings& settings) {
    const Camera& camera = in.camera();
    const Light light = pointLightFor(in.light);
    StageTimer timer;
    const DebugBuffers debug(in.debugDir, "shadow-volume");
    StencilBuffers& kept = in.kept().state<StencilBuffers>();
    KeptFramebuffer fb(kept.memory, camera.width, camera.height, {.stencil = true, .color = debug.enabled()});
    raster::Rasterizer& rasterizer = kept.rasterizer.at(in.simd);
    const StencilPass pass = runStencilPass(rasterizer, *fb, in, settings, homogeneousLight(light), timer);

    ShadowOutputs out = visibilityFromStencil(in.gbuffer, light, fb->stencil().data(), fb->tilesX());
    timer.lap("visibility");
    appendStencilPassStats(in, pass, out.stats);
    timer.appendTo(out.stats);
    if (debug.enabled()) writeDebug(debug, in, out, pass.volume, fillPerPixel(rasterizer, *fb, pass));
    return out;
}

Technique shadowVolumeTechnique() {
    return {.name = "shadow-volume",
            .description = "stencil shadow volumes: silhouettes extruded to infinity, z-pass or z-fail with "
                           "two-sided wrapping stencil",
            .params = stencilPassSettingsTable().specs(),
            .run = [](const ShadowInputs& in) { return runShadowVolume(in, stencilPassSettingsTable().read(in.params)); },
            .referenceName = "reference",
            .output = TechniqueOutput::Visibility,
            .prepare = prepareEdgeAdjacency};
}

}  // namespace shadowlab
