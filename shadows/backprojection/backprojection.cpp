// The `backprojection` technique (backprojection.h). Per camera pixel with a surface:
//   1. the light's samples below the receiver's plane are hidden, as in the reference;
//   2. the light's cone from the receiver, cut at the map's near plane, bounds the texels
//      that can occlude (the PCSS search region at its full size); where the min/max
//      hierarchy proves every texel there lit (min_max_hierarchy.h), the pixel is done;
//   3. else its occluder patches (occluder_patches.h), texels or for a wide region the
//      hierarchy's nodes, are projected onto the light, neighbours on one surface joined
//      (surface_joins.h, once per frame), and set the samples they hide
//      (back_projection.h); V = 1 - hidden / samples.
// Pixels are independent and rows run in parallel, so V is the same for any thread count.
#include "shadows/backprojection/backprojection.h"

#include <algorithm>
#include <string>

#include <tbb/parallel_for.h>

#include "shading/light_sampling.h"
#include "shadows/backprojection/back_projection.h"
#include "shadows/backprojection/light_plot.h"
#include "shadows/backprojection/surface_joins.h"
#include "shadows/debug_buffers.h"
#include "shadows/filtered/blocker_search.h"
#include "shadows/filtered/pcss.h"
#include "shadows/maps/shadow_map_debug.h"
#include "shadows/plot_pixel.h"
#include "shadows/stage_timer.h"

namespace shadowlab {
namespace {

const char* const kBackprojectionName = "backprojection";

struct Settings {
    int resolution = 512;
    int lightSamples = 16;      // per axis of the light's bitmask grid
    int maxNodes = 32;          // texels (or nodes) per side of a search region
    double edgeRatio = 8.0;     // a depth step more than this many times the steps beside it is an edge
    bool minMaxHierarchy = true;
    PlotPixelSettings plot;
};

const SettingsTable<Settings>& settingsTable() {
    using S = Settings;
    static const auto table =
        SettingsTable<S>()
            .include(member(&S::resolution), mapResolutionTable("texels per side of the map"))
            .integer("light-samples", member(&S::lightSamples), 2, kMaxLightSamplesPerAxis,
                     "samples per axis of the light's bitmask grid (n x n bits)")
            .integer("max-nodes", member(&S::maxNodes), 4, 1024,
                     "texels per side of a search region before the hierarchy's nodes stand in")
            .real("edge-ratio", member(&S::edgeRatio), 1.0, 1e6,
                  "a depth step between neighbouring patches more than this many times the steps beside it is an "
                  "edge between two surfaces (else they join: gap closing)")
            .flag("min-max-hierarchy", member(&S::minMaxHierarchy),
                  "skip the pixels whose search region the hierarchy proves lit (same V)")
            .include(member(&S::plot), plotPixelSettingsTable("patches are drawn on the light"));
    return table;
}

// What one pixel's shading found, beside its V (the debug views and stats).
struct PixelResult {
    float visibility = 0.0f;
    int level = -1;             // -1: nothing searched (proved lit, or nearer than the near plane)
    int patches = 0;
    bool proved = false;
};

struct Frame {
    const SoftShadowMap& soft;
    const MinMaxHierarchy& hierarchy;
    const SurfaceJoins& joins;
    const AreaLightPlane plane;
    const AreaLightFrame light;
    const LightGrid samples;
    const Settings settings;
};

// The texels [x0, x1] x [y0, y1] (clamped to the map) that can hide part of the light from
// a receiver at distance dr: the light's cone from it cut at the near plane, then twice cut
// at the least depth the hierarchy finds in the last region (an occluder there is at least
// that far from the light, and the cone narrows with distance).
TexelRect searchRegion(const Frame& f, const MapReceiver& r, double dr) {
    double nearest = f.soft.zNear();
    TexelRect region;
    for (int pass = 0; pass < 3; ++pass) {
        region = coneTexels(f.soft, r.texel, dr, nearest);
        const float least = f.hierarchy.over(region.x0, region.y0, region.x1, region.y1).least;
        if (least >= 1.0f) break;
        nearest = std::clamp(f.soft.distanceOf(least), nearest, dr);
    }
    return region;
}

PixelResult shadePixel(const Frame& f, const glm::dvec3& P, const glm::dvec3& N, PatchGrid& grid,
                       BackProjectionScratch& scratch, std::vector<glm::vec2>* drawn, LightBitmask* shown) {
    PixelResult out;
    LightBitmask hidden;
    // 1. The horizon: light points with dot(N, X - P) <= 0 are behind the surface.
    f.samples.coverHalfPlane(hidden, glm::dot(N, f.light.axisA), glm::dot(N, f.light.axisB),
                             glm::dot(N, f.light.centre - P));
    const double dr = softReceiver(f.soft, P).distance;
    if (!f.samples.full(hidden) && dr > f.soft.zNear()) {
        // 2. The search region: the light's cone cut at the near plane, narrowed to the cone
        //    cut at the nearest depth the region holds (Guennebaud et al., section 4.1).
        const MapReceiver r = planeReceiver(f.soft, P, N);
        const auto [x0, y0, x1, y1] = searchRegion(f, r, dr);
        out.proved = f.settings.minMaxHierarchy && f.hierarchy.provedLit(r, x0, y0, x1, y1);
        if (!out.proved) {
            // 3. The occluders' patches onto the light, those off it left out.
            const LightPyramid pyramid(f.soft, P, f.light);
            gatherPatches(f.soft, f.hierarchy, {r, dr, pyramid, f.samples.perAxis()}, x0, y0, x1, y1,
                          f.settings.maxNodes, grid);
            out.level = grid.level;
            if (grid.occluders > 0) {
                out.patches = backProjectPatches(grid, f.joins, f.soft, P, f.plane, pyramid, f.samples, hidden,
                                                 scratch, drawn);
            }
        }
    }
    out.visibility = 1.0f - float(f.samples.hidden(hidden)) / float(f.samples.sampleCount());
    if (shown) *shown = hidden;
    return out;
}

void writeDebug(const ShadowInputs& in, const Frame& f, const std::vector<int8_t>& level,
                const std::vector<uint16_t>& patches) {
    const DebugBuffers debug(in.debugDir, kBackprojectionName);
    if (!debug.enabled()) return;
    const GBuffer& g = in.gbuffer;
    writeDepthMap(debug, "depth", f.soft.map);
    writeMinMaxHierarchy(debug, f.hierarchy);
    debug.write("level", g.width, g.height, std::vector<float>(level.begin(), level.end()), -1.0f,
                float(f.hierarchy.levels()));
    const float most = float(*std::max_element(patches.begin(), patches.end()));
    debug.write("patches", g.width, g.height, std::vector<float>(patches.begin(), patches.end()), 0.0f,
                std::max(most, 1.0f));
    const auto [i, j] = plotPixel(f.settings.plot, g.width, g.height, kBackprojectionName);
    const size_t k = g.index(i, j);
    if (!g.hit[k]) return;
    PatchGrid grid;
    BackProjectionScratch scratch;
    std::vector<glm::vec2> drawn;
    LightBitmask hidden;
    const PixelResult r =
        shadePixel(f, glm::dvec3(g.position[k]), glm::dvec3(g.normal[k]), grid, scratch, &drawn, &hidden);
    writeLightPlot(in.debugDir / (std::string(kBackprojectionName) + "-light.svg"), f.samples, f.light.disk, hidden, drawn,
                   r.level);
}

ShadowOutputs runBackprojection(const ShadowInputs& in) {
    const Settings s = settingsTable().read(in.params);
    requireAreaLight(in.light, kBackprojectionName);
    plotPixel(s.plot, in.gbuffer.width, in.gbuffer.height, kBackprojectionName);   // settings checked before any work
    const AreaLightFrame light = areaLightFrame(in.light);
    const LightGrid samples(s.lightSamples, light.disk);
    if (!anyReachable(in.gbuffer, in.light)) return unlitOutputs(in.gbuffer);   // settings checked first
    StageTimer timer;
    const SoftShadowMap& soft = renderPcssMap(in, s.resolution);
    timer.lap("map");
    const MinMaxHierarchy hierarchy(soft.map);
    timer.lap("hierarchy");
    const SurfaceJoins joins(soft.map, hierarchy, s.edgeRatio);
    timer.lap("surface_joins");
    const Frame f{soft, hierarchy, joins, areaLightPlane(light), light, samples, s};
    const GBuffer& g = in.gbuffer;
    ShadowOutputs out;
    out.visibility.assign(g.pixelCount(), 0.0f);
    std::vector<int8_t> level(g.pixelCount(), -1);
    std::vector<uint16_t> patches(g.pixelCount(), 0);
    std::vector<uint8_t> proved(g.pixelCount(), 0);
    tbb::parallel_for(0, g.height, [&](int j) {
        PatchGrid grid;
        BackProjectionScratch scratch;
        for (int i = 0; i < g.width; ++i) {
            const size_t k = g.index(i, j);
            if (!g.hit[k]) continue;
            const PixelResult r =
                shadePixel(f, glm::dvec3(g.position[k]), glm::dvec3(g.normal[k]), grid, scratch, nullptr, nullptr);
            out.visibility[k] = r.visibility;
            level[k] = int8_t(r.level), patches[k] = uint16_t(std::min(r.patches, 65535)), proved[k] = r.proved;
        }
    });
    timer.lap("receivers");
    writeDebug(in, f, level, patches);
    timer.lap("debug_buffers");
    // Figures in pixel order (one thread): the same for any thread count.
    size_t surfaces = 0, provedCount = 0, searched = 0, patchSum = 0, coarse = 0;
    for (size_t k = 0; k < g.pixelCount(); ++k) {
        surfaces += g.hit[k], provedCount += proved[k];
        if (level[k] >= 0) ++searched, patchSum += patches[k], coarse += level[k] > 0;
    }
    const auto percent = [&](size_t n) { return surfaces ? 100.0 * double(n) / double(surfaces) : 0.0; };
    out.stats = {{"resolution_texels", double(s.resolution)},
                 {"light_samples_count", double(samples.sampleCount())},
                 {"hierarchy_proved_lit_percent", percent(provedCount)},
                 {"searched_percent", percent(searched)},
                 {"coarse_level_percent", percent(coarse)},
                 {"patches_per_searched_pixel_count", searched ? double(patchSum) / double(searched) : 0.0}};
    timer.appendTo(out.stats);
    return out;
}

}  // namespace

Technique backprojectionTechnique() {
    return {.name = kBackprojectionName,
            .description = "shadow-map texels back-projected onto the area light, hidden light samples in a "
                           "bitmask (Guennebaud et al. 2006, Schwarz and Stamminger 2007)",
            .params = settingsTable().specs(),
            .run = runBackprojection,
            .referenceName = "reference-soft",
            .output = TechniqueOutput::Visibility};
}

}  // namespace shadowlab
