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
//   3. an N x N grid (N = `filter-nodes`) over the width w, read at the first level where w
//      spans at most N nodes: a node proved lit counts lit, one whose greatest depth is
//      nearer than the plane counts shadowed, and a mixed node takes the texel at the tap
//      (a point sample, as a mip of depths can hold nothing better).
// So a penumbra costs the same taps however wide it is: the sharp contact reads texels, the
// wide far penumbra coarse nodes. V is the lit fraction; no blocker: 1. Pixels are
// independent, so V is the same for any thread count.
#include <algorithm>
#include <cmath>

#include "shadows/debug_buffers.h"
#include "shadows/filtered/blocker_search.h"
#include "shadows/filtered/pcss.h"
#include "shadows/filtered/soft_shadow_techniques.h"
#include "shadows/maps/min_max_hierarchy.h"
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
                     "filter: N x N taps, read at the level that fits them");
    return table;
}

struct Estimate {
    double blockerDistance = 0.0;   // 0: no blocker
    int level = 0;
};

// Steps 1 and 2: the blockers' mean distance, from the nodes of the search region.
Estimate searchBlockers(const SoftShadowMap& soft, const MinMaxHierarchy& h, const MapReceiver& r, double dr,
                        int nodes) {
    const auto [x0, y0, x1, y1] = coneTexels(soft, r.texel, dr, soft.zNear());
    Estimate e;
    if (h.provedLit(r, x0, y0, x1, y1)) return e;   // no node could hold a blocker: skip the search
    e.level = readingLevelFor(std::max(x1 - x0, y1 - y0), nodes, h.levels());
    double sum = 0.0;
    int blockers = 0;
    for (int y = y0 >> e.level; y <= y1 >> e.level; ++y) {
        for (int x = x0 >> e.level; x <= x1 >> e.level; ++x) {
            // The node's least depth is a blocker wherever in the node it lies: a sufficient
            // test, so no floor node counts (a necessary one, not proved lit, would count
            // every node the proof cannot settle, at the floor's own depth).
            const float least = e.level == 0 ? soft.map.at(x, y) : h.node(e.level, x, y).least;
            if (least < 1.0f && double(least) + r.tolerance < planeLeastOver(r, e.level, x, y)) {
                sum += soft.distanceOf(least), ++blockers;
            }
        }
    }
    if (blockers) e.blockerDistance = std::clamp(sum / blockers, soft.zNear(), dr);
    return e;
}

// Step 3: the N x N grid over the filter's width, each tap answered by its node.
double filterGrid(const SoftShadowMap& soft, const MinMaxHierarchy& h, const MapReceiver& r, glm::dvec2 radius,
                  int n, int& level) {
    radius = glm::max(radius, glm::dvec2(0.5));
    level = readingLevelFor(int(std::ceil(2.0 * std::max(radius.x, radius.y))), n, h.levels());
    const int last = soft.map.size - 1;
    int lit = 0;
    for (int b = 0; b < n; ++b) {
        for (int a = 0; a < n; ++a) {
            const glm::dvec2 at = r.texel + radius * glm::dvec2((2.0 * a + 1.0) / n - 1.0, (2.0 * b + 1.0) / n - 1.0);
            const int tx = std::clamp(texelIndexOf(at.x), 0, last), ty = std::clamp(texelIndexOf(at.y), 0, last);
            if (level == 0) {
                lit += r.litBy(soft.map, tx, ty);
                continue;
            }
            const int x = tx >> level, y = ty >> level;
            if (h.nodeProvedLit(r, level, x, y)) {
                ++lit;
            } else if (!h.nodeShadowed(r, level, x, y)) {
                lit += r.litBy(soft.map, tx, ty);   // mixed: the texel at the tap
            }
        }
    }
    return double(lit) / double(n * n);
}

ShadowOutputs runChs(const ShadowInputs& in) {
    const ChsSettings s = chsSettingsTable().read(in.params);
    requireAreaLight(in.light, kChsName);
    if (!anyReachable(in.gbuffer, in.light)) return unlitOutputs(in.gbuffer);   // settings checked first
    StageTimer timer;
    const SoftShadowMap soft = renderPcssMap(in, s.resolution);
    timer.lap("map");
    const MinMaxHierarchy h(soft.map);
    timer.lap("hierarchy");
    const GBuffer& g = in.gbuffer;
    ShadowOutputs out;
    out.visibility.assign(g.pixelCount(), 0.0f);
    std::vector<float> filterLevel(g.pixelCount(), -1.0f);
    struct Row {};
    forEachReceiverFacingLight<Row>(
        g, soft,
        [&](Row&, size_t k, const glm::dvec3& P, const glm::dvec3& N, const SoftReceiver& receiver) {
            const MapReceiver r = planeReceiver(soft, P, N);
            const Estimate e = searchBlockers(soft, h, r, receiver.distance, s.searchNodes);
            out.visibility[k] = 1.0f;
            if (e.blockerDistance <= 0.0) return;
            const glm::dvec2 radius = 0.5 * sampleWidthTexels(soft, receiver.distance, e.blockerDistance);
            int level = 0;
            out.visibility[k] = float(filterGrid(soft, h, r, radius, s.filterNodes, level));
            filterLevel[k] = float(level);
        },
        [](Row&) {});
    timer.lap("receivers");
    const DebugBuffers debug(in.debugDir, kChsName);
    if (debug.enabled()) {
        writeDepthMap(debug, "depth", soft.map);
        writeMinMaxHierarchy(debug, h);
        debug.write("filter-level", g.width, g.height, filterLevel, -1.0f, float(h.levels()));
    }
    size_t filtered = 0, coarse = 0;   // in pixel order: the same for any thread count
    for (float l : filterLevel) filtered += l >= 0.0f, coarse += l > 0.0f;
    out.stats = {{"resolution_texels", double(s.resolution)},
                 {"filtered_pixels", double(filtered)},
                 {"coarse_filter_percent", filtered ? 100.0 * double(coarse) / double(filtered) : 0.0}};
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
