// The `chs` technique: contact-hardening soft shadows, PCSS on the levels of a mip chain
// (Real-Time Rendering, 4th ed., 7.6: "first generating mipmaps of the shadow map, then
// choosing the mip level closest to a user-defined world-space kernel size. An 8 x 8 area
// is sampled to find the average blocker depth ... the higher-resolution mip levels are used
// for the sharp area of the shadow, while the lower-resolution mip levels are used for
// softer areas"; Sikachev et al.). Depths cannot be averaged, so the chain is the min/max
// hierarchy (min_max_hierarchy.h). Per camera pixel, on the receiver's plane:
//   1. blocker search: the light's cone cut at the near plane, read at the first level where
//      it spans at most `search-nodes` nodes a side; a node whose least depth is nearer than
//      the receiver's plane anywhere over it holds a blocker, at that depth; d_o is their mean;
//   2. eq. 7.6 gives the filter's width w, as PCSS;
//   3. an N x N grid (N = `filter-nodes`) over the width w, each tap the texel it falls in
//      (a mip of depths holds nothing better than a point sample); where the hierarchy
//      proves a footprint lit or shadowed, its taps are skipped.
// So the search costs the same nodes however wide the penumbra is: the sharp contact reads
// texels, the wide far penumbra coarse nodes. V is the lit fraction; no blocker: 1. The
// three steps run in float in the shadow lookup's vector kernel (shadows/maps/
// lookup_kernel.inl, filter kLookupChs), rows in parallel; V is the same bytes for any
// thread count and SIMD level.
#include <utility>
#include <vector>

#include "shadows/debug_buffers.h"
#include "shadows/filtered/pcss.h"
#include "shadows/filtered/soft_shadow_techniques.h"
#include "shadows/maps/min_max_hierarchy.h"
#include "shadows/maps/shadow_lookup.h"
#include "shadows/maps/shadow_map_debug.h"
#include "shadows/settings_table.h"
#include "shadows/stage_timer.h"

namespace shadowlab {
namespace {

const char* const kChsName = "chs";

struct ChsSettings {
    int resolution = kSoftMapResolution;
    int searchNodes = 8;   // per side of the search region's level
    int filterNodes = 8;   // N of the N x N filter grid
};

const SettingsTable<ChsSettings>& chsSettingsTable() {
    using S = ChsSettings;
    static const auto table =
        SettingsTable<S>()
            .include(member(&S::resolution), mapResolutionTable("texels per side of the map"))
            .integer("search-nodes", member(&S::searchNodes), 2, 64,
                     "blocker search: nodes per side of the region's level")
            .integer("filter-nodes", member(&S::filterNodes), 2, 64,
                     "filter: N x N taps over the eq. 7.6 width");
    return table;
}

ShadowOutputs runChs(const ShadowInputs& in) {
    const ChsSettings s = chsSettingsTable().read(in.params);
    requireAreaLight(in.light, kChsName);
    if (!anyReachable(in.gbuffer, in.light)) return unlitOutputs(in.gbuffer);   // settings checked first
    StageTimer timer;
    const SoftShadowMap& soft = renderPcssMap(in, s.resolution);
    timer.lap("map");
    const MinMaxHierarchy h(soft.map);
    timer.lap("hierarchy");
    const GBuffer& g = in.gbuffer;
    const size_t n = g.pixelCount();
    std::vector<float> visibility(n), blockerDistance(n), width(n), searchLevel(n);
    const LookupPass pass(soft.map, soft.light, {s.searchNodes, s.filterNodes, soft.lightTexels, h.forKernel()},
                          in.simd);
    lookUpEveryRow(g, pass, {visibility.data(), blockerDistance.data(), width.data(), nullptr, searchLevel.data()});
    timer.lap("receivers");
    const DebugBuffers debug(in.debugDir, kChsName);
    if (debug.enabled()) {
        writeDepthMap(debug, "depth", soft.map);
        writeMinMaxHierarchy(debug, h);
        debug.write("search-level", g.width, g.height, searchLevel, 0.0f, float(h.levels()));
    }
    size_t filtered = 0, coarse = 0;   // in pixel order: the same for any thread count
    for (size_t k = 0; k < n; ++k) filtered += blockerDistance[k] > 0.0f, coarse += searchLevel[k] > 0.0f;
    ShadowOutputs out;
    out.visibility = std::move(visibility);
    out.stats = {{"resolution_texels", double(s.resolution)},
                 {"filtered_pixels", double(filtered)},
                 {"coarse_search_percent", filtered ? 100.0 * double(coarse) / double(filtered) : 0.0}};
    timer.appendTo(out.stats);
    return out;
}

}  // namespace

Technique contactHardeningTechnique() {
    return {.name = kChsName,
            .description = "contact-hardening soft shadows: PCSS read on the levels of a min/max mip chain (RTR 7.6, "
                           "Sikachev et al.)",
            .params = chsSettingsTable().specs(),
            .run = runChs,
            .referenceName = "reference-soft",
            .output = TechniqueOutput::Visibility};
}

}  // namespace shadowlab
