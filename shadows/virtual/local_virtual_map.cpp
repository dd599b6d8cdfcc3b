#include "shadows/virtual/local_virtual_map.h"

#include <optional>

#include "scenes/bounds.h"
#include "shadows/debug_buffers.h"
#include "shadows/stage_timer.h"
#include "shadows/virtual/local_invalidation.h"
#include "shadows/virtual/local_lookup.h"
#include "shadows/virtual/local_marking.h"
#include "shadows/virtual/local_page_rendering.h"
#include "shadows/virtual/local_ray_samples.h"
#include "shadows/virtual/local_smrt.h"
#include "shadows/virtual/page_invalidation.h"
#include "shadows/virtual/mip_chain.h"
#include "shadows/virtual/page_lookup.h"
#include "shadows/virtual/virtual_debug.h"
#include "shadows/virtual/virtual_stats.h"

namespace shadowlab::vsm {
namespace {

// What the technique keeps from frame to frame for a local light.
struct LocalMapState {
    std::optional<PageTable> table;
    PagePool pool;
    Light light;                     // the point or spot light the chain was made for
    MipChain chain;
    std::vector<Aabb> casterBoxes;   // the last frame's, per instance
    uint64_t geometryVersion = 0;    // the prepared scene's when they were taken
    std::vector<PixelLevel> levels;  // marking's, per pixel
    PageDrawing drawing;
};

// Whether every texel of a chain made for `a` is the same for `b`.
bool sameFaces(const Light& a, const Light& b) {
    return a.type == b.type && a.position == b.position && a.direction == b.direction &&
           a.coneAngleDeg == b.coneAngleDeg;
}

// The state ready for this frame: made on the first, reset when the light moved or turned
// or the casters left the depth range; the pages under casters that moved invalidated.
// Returns how many valid pages were invalidated.
int prepareState(LocalMapState& state, const LocalMapSettings& s, const Light& light, const std::vector<Aabb>& boxes) {
    const bool fresh = !state.table || !sameFaces(state.light, light) || boxes.size() != state.casterBoxes.size() ||
                       !state.chain.range.holds(depthRangeAround(boxes, state.chain.apex, state.chain.tanHalf, true));
    if (fresh) {
        const int before = state.table ? state.table->residentPages() : 0;
        state.chain = mipChainFor(light, s.clipmap, boxes);
        if (!state.table || state.table->layout() != state.chain.layout()) {
            state.table.emplace(state.chain.layout(), s.poolPages);
            state.pool = {s.clipmap.pageTexels, {}};
        }
        state.table->invalidateAll();
        state.light = light, state.casterBoxes = boxes;
        return before;
    }
    const std::vector<Aabb> moved = movedBoxes(state.casterBoxes, boxes);
    state.casterBoxes = boxes;
    return invalidateLocalUnder(moved, state.chain, *state.table);
}

}  // namespace

ShadowOutputs runLocalVirtualMap(const ShadowInputs& in, const LocalMapSettings& s) {
    if (!anyReachable(in.gbuffer, in.light)) return unlitOutputs(in.gbuffer);
    StageTimer timer;
    LocalMapState& state = in.kept().state<LocalMapState>();
    // 1. The chain; what moved. The boxes are the last frame's unless an instance moved
    // since (the prepared scene's geometry version).
    const bool moved = !state.table || state.geometryVersion != in.prepared.geometryVersion();
    const std::vector<Aabb> boxes = moved ? instanceBounds(in.casters().scene(), in.casterWorld()) : state.casterBoxes;
    state.geometryVersion = in.prepared.geometryVersion();
    const int invalidated = prepareState(state, s, pointLightFor(in.light), boxes);
    const MipChain& chain = state.chain;
    PageTable& table = *state.table;
    timer.lap("invalidation");
    // 2. Marking: every mip's window is the whole mip.
    table.beginFrame(chain.windows());
    markLocalPages(in.gbuffer, in.camera(), in.light, chain, {s.lodBias, lookupReachTexels(s.bias, s.filter)}, table, state.levels);
    std::optional<LocalRaySamples> samples;   // the rays' samples, where there are rays
    if (s.smrt.rays > 0) {
        samples.emplace(chain, in.light, s.bias, s.smrt);
        markLocalRayPages(in.gbuffer, *samples, state.levels, table);
    }
    timer.lap("marking");
    // 3. Memory, and the pages to render.
    const std::vector<PageKey> toRender = table.allocate();
    std::vector<int32_t> physical;
    for (const PageKey& key : toRender) physical.push_back(table.physical(key));
    timer.lap("allocation");
    // 4. The pages drawn.
    renderLocalPages(in.casters(), boxes, chain, toRender, physical, polygonOffsetFor(s.bias), in.simd, state.drawing,
                     state.pool);
    for (const PageKey& key : toRender) table.markRendered(key);
    timer.lap("pages");
    // 5. The lookup.
    SmrtResult rays;
    if (samples)
        rays = traceLocalShadowMapRays(in.gbuffer, in.light, *samples, s.smrt, state.levels, table, state.pool);
    else
        rays.lookup = lookUpLocalPages(in.gbuffer, in.light, chain, s.bias, makePcfKernel(s.filter, in.frameIndex), state.levels,
                                       table, state.pool);
    LookupResult& lookup = rays.lookup;
    timer.lap("lookup");
    ShadowOutputs out;
    out.visibility = std::move(lookup.visibility);
    addPageStats(out, table, toRender.size(), invalidated, lookup, state.pool);
    out.stats.push_back({"faces_count", double(chain.faceCount())});
    out.stats.push_back({"mips_count", double(chain.mipCount)});
    if (s.smrt.rays > 0) out.stats.push_back({"smrt_missing_read_count", double(rays.missingReads)});
    timer.appendTo(out.stats);
    writeLocalVirtualDebug(DebugBuffers(in.debugDir, "virtual-shadow-map"), in.gbuffer, in.camera(), chain,
                           state.levels, table, toRender, state.pool, rays.escapedRays);
    return out;
}

}  // namespace shadowlab::vsm
