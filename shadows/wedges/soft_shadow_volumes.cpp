// `soft-shadow-volumes`: soft shadows of a disk or rectangle light by penumbra wedges
// (Akenine-Möller and Assarsson 2002, "Approximate Soft Shadows on Arbitrary Surfaces using
// Penumbra Wedges"; Assarsson and Akenine-Möller 2003, "A Geometry-based Soft Shadow
// Volume Algorithm using Graphics Hardware"; docs/accurate-soft-shadows.md). Per frame:
//
//   1. the silhouette edges of the light's centre and the hard shadow of the centre,
//      counted in the stencil: the shadow volume's pass (shadows/volumes/stencil_pass.h,
//      params `mode` and `offset` as for `shadow-volume`); V_hard = 1 where the count is 0;
//   2. one wedge per silhouette edge (wedge_construction.h);
//   3. the wedges drawn over the receivers' depth and, per pixel inside a wedge, the edge's
//      signed coverage of the light added up (wedge_rasterization.h, edge_coverage.h),
//      made to agree with the stencil where the centre lies on an edge (hard_boundary.h);
//      V_hard is, by param `hard-shadow`, 1 - the stencil count read as signed (`count`,
//      the default: the winding number edge_coverage.h's sum starts from) or 1 where the
//      count is 0 and 0 elsewhere (`binary`, the hard shadow as `shadow-volume` gives it);
//      the two differ only where the centre is behind more than one occluder;
//   4. V = clamp(V_hard - sum, 0, 1), and V = 0 where the light's centre is behind the
//      receiver (dot(N, c - P) <= 0), as for the hard techniques. The reference counts
//      the light's samples above the receiver's plane instead; a receiver whose plane cuts
//      the light is the one place the two differ by that rule.
//
// Known error (the paper's): the silhouette is the centre's, and overlapping silhouettes
// count twice, so where two occluders overlap as seen from the light the covered area is
// summed, not united. With `count` the shadow is then too dark by the doubly hidden share;
// with `binary` too dark where the centre is visible or hidden once, too light where it
// is hidden twice (measured in the doc and the tests).
#include "shadows/wedges/soft_shadow_volumes.h"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include <tbb/parallel_for.h>

#include "shading/light_sampling.h"
#include "shading/lights.h"
#include "shadows/debug_buffers.h"
#include "shadows/silhouettes/silhouette.h"
#include "shadows/stage_timer.h"
#include "shadows/volumes/stencil_pass.h"
#include "shadows/wedges/edge_coverage.h"
#include "shadows/wedges/hard_boundary.h"
#include "shadows/wedges/wedge_construction.h"
#include "shadows/wedges/wedge_rasterization.h"

namespace shadowlab {
namespace {

constexpr const char* kSoftShadowVolumesName = "soft-shadow-volumes";

enum class HardShadow { Count, Binary };   // the `hard-shadow` parameter

struct SoftShadowVolumeSettings {
    StencilPassSettings pass;
    HardShadow hardShadow = HardShadow::Count;
};

const SettingsTable<SoftShadowVolumeSettings>& softShadowVolumeSettingsTable() {
    using S = SoftShadowVolumeSettings;
    static const auto table =
        SettingsTable<S>()
            .include(member(&S::pass), stencilPassSettingsTable())
            .choice("hard-shadow", member(&S::hardShadow),
                    {{"count", HardShadow::Count,
                      "V_hard = 1 - the stencil count: overlaps darken by the doubly hidden share"},
                     {"binary", HardShadow::Binary, "V_hard = 1 where the count is 0: the shadow-volume's hard shadow"}},
                    "how the centre's hard shadow enters V");
    return table;
}

// Step 4, with the hard shadow of the centre from the stencil (row-major); rows in
// parallel, each pixel written by its own row: the same bytes for any thread count.
ShadowOutputs finalVisibility(const GBuffer& g, const Light& centre, const std::vector<uint8_t>& stencil,
                              const WedgeCoverage& wedges, HardShadow mode) {
    ShadowOutputs out;
    out.visibility.assign(g.pixelCount(), 0.0f);
    out.stencil.resize(g.pixelCount());
    const LightReach reaches(centre);
    tbb::parallel_for(0, g.height, [&](int j) {
        for (int i = 0; i < g.width; ++i) {
            const size_t k = g.index(i, j);
            out.stencil[k] = float(int8_t(stencil[k]));
            if (!g.hit[k] || !reaches(g.position[k], g.normal[k])) continue;
            const float count = out.stencil[k];
            const float hard = mode == HardShadow::Count ? 1.0f - count : (count == 0.0f ? 1.0f : 0.0f);
            out.visibility[k] = std::clamp(hard - float(wedges.correction[k]), 0.0f, 1.0f);
        }
    });
    return out;
}

void addWedgeStats(const WedgeSet& set, const WedgeCoverage& c, uint64_t flipped, size_t pixels,
                   std::vector<TechniqueStat>& stats) {
    stats.insert(stats.end(), {
        {"wedges_count", double(set.wedges.size())},
        {"unbounded_edges", double(set.unboundedEdges.size())},
        {"wedge_triangles", double(set.triangles.size())},
        {"near_plane_wedges_count", double(c.nearWedges)},
        {"wedge_fill_fragments", double(c.fillFragments)},
        {"wedge_fragments", double(c.listedFragments)},
        {"wedge_inside_fragments", double(c.insideFragments)},
        {"wedge_inside_fragments_per_pixel", double(c.insideFragments) / double(pixels)},
        {"near_centre_fragments", double(c.nearCentre.size())},
        {"stencil_side_fragments", double(flipped)},
    });
}

void writeDebug(const DebugBuffers& debug, const Camera& camera, const ShadowOutputs& out, const WedgeCoverage& c) {
    debug.write("stencil", camera.width, camera.height, out.stencil, -4.0f, 4.0f);
    debug.write("wedges", camera.width, camera.height, c.wedgeCount, 0.0f, 8.0f);
    debug.write("correction", camera.width, camera.height, std::vector<float>(c.correction.begin(), c.correction.end()),
                -1.0f, 1.0f);
    debug.write("visibility", camera.width, camera.height, out.visibility, 0.0f, 1.0f);
}

ShadowOutputs runSoftShadowVolumes(const ShadowInputs& in) {
    const SoftShadowVolumeSettings settings = softShadowVolumeSettingsTable().read(in.params);
    if (in.light.type != LightType::Disk && in.light.type != LightType::Rectangle)
        throw std::invalid_argument(std::string(kSoftShadowVolumesName) + ": needs an area light (disk or rectangle)");
    const AreaLightFrame frame = areaLightFrame(in.light);
    const Light centre = pointLightFor(in.light);
    const Camera& camera = in.camera();
    StageTimer timer;
    raster::Framebuffer fb(camera.width, camera.height, {.stencil = true, .fragments = true});
    raster::Rasterizer rasterizer(in.simd);
    const StencilPass pass = runStencilPass(rasterizer, fb, in, settings.pass, homogeneousLight(centre), timer);

    const std::vector<SilhouetteEdge>& silhouette = pass.volume.silhouette;
    const WedgeSet wedges = buildWedges(in.casterWorld().positions, silhouette, lightBall(frame));
    timer.lap("wedges");
    WedgeCoverage coverage = rasterizeWedges(rasterizer, fb, camera, pass.clipFromWorld, wedges,
                                                   {in.casterWorld().positions, silhouette}, areaLightPlane(frame),
                                                   in.gbuffer);
    timer.lap("coverage");
    const uint64_t flipped = reconcileHardBoundary(rasterizer, fb, in, pass, coverage);
    timer.lap("hard_boundary");
    ShadowOutputs out =
        finalVisibility(in.gbuffer, centre, fb.stencilImage(), coverage, settings.hardShadow);
    timer.lap("visibility");
    appendStencilPassStats(in, pass, out.stats);
    addWedgeStats(wedges, coverage, flipped, in.gbuffer.pixelCount(), out.stats);
    timer.appendTo(out.stats);
    const DebugBuffers debug(in.debugDir, kSoftShadowVolumesName);
    if (debug.enabled()) writeDebug(debug, camera, out, coverage);
    return out;
}

}  // namespace

Technique softShadowVolumeTechnique() {
    return {.name = kSoftShadowVolumesName,
            .description = "soft shadow volumes: penumbra wedges on the centre's silhouette edges over its stencil "
                           "hard shadow, the light's covered area per pixel computed exactly",
            .params = softShadowVolumeSettingsTable().specs(),
            .run = runSoftShadowVolumes,
            .referenceName = "reference-soft",
            .output = TechniqueOutput::Visibility,
            .prepare = prepareEdgeAdjacency};
}

}  // namespace shadowlab
