// The technique's frame, stage by stage (docs/virtual-shadow-maps.md):
//   1. the light's frame and depth range; what moved since the last frame invalidates
//      (page_invalidation.h);
//   2. the levels' windows around the camera and the pages the pixels mark (page_marking.h);
//   3. memory for the marked pages and the list of those to render (page_table.h);
//   4. those pages drawn (page_rendering.h);
//   5. the lookup (page_lookup.h);
//   6. on request, the buffers (virtual_debug.h).
// The page table, the pool and what the last frame saw are the technique's state in its
// history (technique_history.h): a frame that stands alone starts from nothing and renders
// every page it marks. A spot, point or area light takes the same stages through its faces'
// mip chains instead (local_virtual_map.h).
#include "shadows/virtual/virtual_shadow_map.h"

#include <optional>
#include <stdexcept>

#include "scenes/bounds.h"
#include "shadows/debug_buffers.h"
#include "shadows/maps/shadow_map_settings.h"
#include "shadows/stage_timer.h"
#include "shadows/virtual/local_virtual_map.h"
#include "shadows/virtual/page_invalidation.h"
#include "shadows/virtual/page_lookup.h"
#include "shadows/virtual/page_marking.h"
#include "shadows/virtual/page_rendering.h"
#include "shadows/virtual/smrt.h"
#include "shadows/virtual/virtual_debug.h"
#include "shadows/virtual/virtual_stats.h"

namespace shadowlab::vsm {
namespace {

const char* const kVirtualMapName = "virtual-shadow-map";

struct VirtualMapSettings {
    ClipmapSettings clipmap;
    int poolPages = 1024;
    int lodBias = 0;
    BiasSettings bias = {};
    FilterSettings filter = {};
    SmrtSettings smrt = {};
};

const SettingsTable<VirtualMapSettings>& virtualMapSettingsTable() {
    using S = VirtualMapSettings;
    static const auto table =
        SettingsTable<S>()
            .integer("virtual-resolution", member(&S::clipmap, &ClipmapSettings::resolution), 256, 1 << 20,
                     "texels a side of each level, and of a local light's faces at mip 0 (a power of two); only "
                     "marked pages are drawn")
            .integer("page-texels", member(&S::clipmap, &ClipmapSettings::pageTexels), 16, 4096,
                     "texels a side of a page (a power of two)")
            .integer("first-level", member(&S::clipmap, &ClipmapSettings::firstLevel), -kMaxLevel, kMaxLevel,
                     "the finest level: 2^(l+1) m a side")
            .integer("last-level", member(&S::clipmap, &ClipmapSettings::lastLevel), -kMaxLevel, kMaxLevel,
                     "the coarsest level: 2^(l+1) m a side")
            .integer("pool-pages", member(&S::poolPages), 1, 1 << 20, "physical pages of memory")
            .integer("lod-bias", member(&S::lodBias), -8, 8, "levels coarser (+) or finer (-) than the pixels' footprint")
            .include(member(&S::bias), biasSettingsTable())
            .include(member(&S::filter), filterSettingsTable())
            .integer("smrt-rays", member(&S::smrt, &SmrtSettings::rays), 0, 256,
                     "shadow-map ray tracing: rays per pixel towards the sun's disk or the light's area; 0: the lookup above")
            .integer("smrt-steps", member(&S::smrt, &SmrtSettings::steps), 1, 64, "shadow-map ray tracing: samples per ray")
            .real("smrt-reach", member(&S::smrt, &SmrtSettings::reachTexels), 0.5, 64.0,
                  "shadow-map ray tracing: texels a ray drifts across a level before reading a coarser one")
            .real("smrt-max-slope", member(&S::smrt, &SmrtSettings::maxSlope), 0.0, 1000.0,
                  "shadow-map ray tracing: the depth history's slope bound, m along the beam per m across")
            .integer("smrt-refinements", member(&S::smrt, &SmrtSettings::refinements), 0, 16,
                     "shadow-map ray tracing: halvings of the step where a ray comes out in front of the map");
    return table;
}

// The sun's cone: half its angular diameter, radians (0: a point-like sun, every ray along
// the beam).
double sunHalfAngle(const Light& sun) { return glm::radians(double(sun.angularDiameterDeg)) / 2.0; }

// What the technique keeps from frame to frame.
struct VirtualMapState {
    std::optional<PageTable> table;
    PagePool pool;
    glm::dvec3 towardsLight{0.0};
    DepthRange range;
    std::vector<Aabb> casterBoxes;   // the last frame's, per instance
    uint64_t geometryVersion = 0;    // the prepared scene's when they were taken
    std::vector<PixelLevel> levels;  // marking's, per pixel
    PageDrawing drawing;
};

// The state ready for this frame: made on the first, reset when the light turned or the
// casters left the depth range; the pages under casters that moved invalidated. Returns how
// many valid pages were invalidated.
int prepareState(VirtualMapState& state, const VirtualMapSettings& s, const glm::dvec3& towardsLight,
                 const LightFrame& frame, const std::vector<Aabb>& boxes) {
    const DepthRange needed = depthRangeOf(boxes, frame);
    const bool fresh = !state.table || towardsLight != state.towardsLight || !state.range.holds(needed) ||
                       boxes.size() != state.casterBoxes.size();
    if (fresh) {
        const int before = state.table ? state.table->residentPages() : 0;
        if (!state.table) state.table.emplace(s.clipmap, s.poolPages), state.pool = {s.clipmap.pageTexels, {}};
        state.table->invalidateAll();
        state.towardsLight = towardsLight, state.range = needed, state.casterBoxes = boxes;
        return before;
    }
    const std::vector<Aabb> moved = movedBoxes(state.casterBoxes, boxes);
    state.casterBoxes = boxes;
    return invalidateUnder(moved, frame, s.clipmap, *state.table);
}

ShadowOutputs runVirtualShadowMap(const ShadowInputs& in) {
    const VirtualMapSettings s = virtualMapSettingsTable().read(in.params);
    checkClipmapSettings(s.clipmap);
    // The rays replace the lookup, filter and all: a filter beside them would go unread.
    if (s.smrt.rays > 0 && s.filter.kind != FilterKind::Nearest)
        throw std::invalid_argument(std::string(kVirtualMapName) +
                                    ": smrt-rays replaces the lookup's filter; give filter=nearest (the default) with it");
    if (in.light.type != LightType::Directional) {
        return runLocalVirtualMap(in, {s.clipmap, s.poolPages, s.lodBias, s.bias, s.filter, s.smrt});
    }
    if (!anyReachable(in.gbuffer, in.light)) return unlitOutputs(in.gbuffer);
    StageTimer timer;
    VirtualMapState& state = in.kept().state<VirtualMapState>();
    // 1. The light's frame; what moved.
    const glm::dvec3 towardsLight = glm::normalize(glm::dvec3(in.light.direction));
    const LightFrame frame = LightFrame::towards(towardsLight);
    // The casters' boxes: the last frame's unless an instance moved since (the prepared
    // scene's geometry version), so that a steady frame makes no pass over the vertices.
    const bool moved = !state.table || state.geometryVersion != in.prepared.geometryVersion();
    const std::vector<Aabb> boxes =
        moved ? instanceBounds(in.casters().scene(), in.casterWorld()) : state.casterBoxes;
    state.geometryVersion = in.prepared.geometryVersion();
    const int invalidated = prepareState(state, s, towardsLight, frame, boxes);
    PageTable& table = *state.table;
    timer.lap("invalidation");
    // 2. Windows and marking.
    std::vector<LevelWindow> windows;
    const glm::dvec3 eye = frame.local(glm::dvec3(in.camera().eye));
    for (int l = s.clipmap.firstLevel; l <= s.clipmap.lastLevel; ++l) windows.push_back(placeLevel(s.clipmap, l, eye));
    table.beginFrame(windows);
    const double halfAngle = sunHalfAngle(in.light);
    const MarkingSettings marking{s.lodBias, lookupReachTexels(s.bias, s.filter),
                                  smrtReach(s.smrt, halfAngle, state.range)};
    markPages(in.gbuffer, in.camera(), in.light, frame, s.clipmap, marking, table, state.levels);
    const std::vector<PixelLevel>& levels = state.levels;
    timer.lap("marking");
    // 3. Memory, and the pages to render.
    const std::vector<PageKey> toRender = table.allocate();
    std::vector<int32_t> physical;
    for (const PageKey& key : toRender) physical.push_back(table.physical(key));
    timer.lap("allocation");
    // 4. The pages drawn.
    renderPages(in.casters(), boxes, frame, s.clipmap, state.range, toRender, physical, polygonOffsetFor(s.bias),
                in.simd, state.drawing, state.pool);
    for (const PageKey& key : toRender) table.markRendered(key);
    timer.lap("pages");
    // 5. The lookup.
    SmrtResult rays;
    if (s.smrt.rays > 0)
        rays = traceShadowMapRays(in.gbuffer, in.light, frame, s.clipmap, state.range, s.bias, s.smrt, marking, levels,
                                  table, state.pool);
    else
        rays.lookup = lookUpPages(in.gbuffer, in.light, frame, s.clipmap, state.range, s.bias,
                                  makePcfKernel(s.filter, in.frameIndex), levels, table, state.pool);
    LookupResult& lookup = rays.lookup;
    timer.lap("lookup");
    ShadowOutputs out;
    out.visibility = std::move(lookup.visibility);
    addPageStats(out, table, toRender.size(), invalidated, lookup, state.pool);
    if (s.smrt.rays > 0) out.stats.push_back({"smrt_missing_read_count", double(rays.missingReads)});
    timer.appendTo(out.stats);
    writeVirtualDebug(DebugBuffers(in.debugDir, kVirtualMapName), in.gbuffer, in.camera(), s.clipmap, levels, table,
                      toRender, state.pool, rays.escapedRays);
    return out;
}

}  // namespace
}  // namespace shadowlab::vsm

namespace shadowlab {

Technique virtualShadowMapTechnique() {
    using namespace vsm;
    return {.name = kVirtualMapName,
            .description = "virtual shadow map (Fernando et al. 2001, Lefohn et al. 2007, UE5's layout): a sun's "
                           "clipmap of 16k levels, or a local light's faces' mip chains, in pages; only the marked "
                           "pages rendered, cached across frames",
            .params = virtualMapSettingsTable().specs(),
            .run = runVirtualShadowMap,
            .referenceName = "reference",
            .output = TechniqueOutput::Visibility};
}

}  // namespace shadowlab
