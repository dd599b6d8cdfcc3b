// The `pcss` technique: percentage-closer soft shadows (Fernando 2005; Real-Time Rendering,
// 4th ed., section 7.6). Per camera pixel: the blocker search and the penumbra width of
// eq. 7.6 (blocker_search.h), then percentage-closer filtering (RTR 7.5) over a rotated
// Poisson disk of that width (pcf.h). Pixels are independent and rows run in parallel;
// the only per-pixel randomness is the disk's rotation hashed from the pixel index (or, with
// rotation=ign, interleaved gradient noise at the frame: pcf.h), so V
// is the same bytes for any thread count.
#include <algorithm>
#include <stdexcept>

#include "shadows/debug_buffers.h"
#include "shadows/filtered/pcss.h"
#include "shadows/maps/shadow_map_settings.h"
#include "shadows/filtered/soft_shadow_techniques.h"
#include "shadows/maps/pcf.h"
#include "shadows/maps/shadow_lookup.h"
#include "shadows/maps/shadow_map_debug.h"
#include "shadows/stage_timer.h"

namespace shadowlab {
namespace {

// Beyond the blocker search's reach (soft_shadow_map.h), which also bounds the filter's:
// the PCF radius is never below half a texel and its taps round to the texel they fall in.
constexpr double kSearchFitMarginTexels = 1.5;

// The share of the taps a per-pixel PCSS takes (the search's at every pixel the light
// reaches, the filter's where the search found blockers) whose answers were proved, summed
// in pixel order: the same figure for any thread count and SIMD level. The pass left V = 0
// and no blocker exactly where the light does not reach (a reached pixel without blockers
// is lit, V = 1), so the reach is read from its outputs, not tested again.
double knownTapsPercent(const PcssBuffers& b, const PcssSettings& settings) {
    double taken = 0.0, known = 0.0;
    for (size_t k = 0; k < b.visibility.size(); ++k) {
        const bool blockers = b.blockerDistance[k] > 0.0f;
        if (!blockers && b.visibility[k] == 0.0f) continue;
        taken += settings.search.taps + (blockers ? settings.filterTaps : 0);
        known += b.knownTaps[k];
    }
    return taken > 0.0 ? 100.0 * known / taken : 0.0;
}

void writeDebug(const ShadowInputs& in, const SoftShadowMap& soft, const PcssBuffers& b,
                const std::optional<MinMaxHierarchy>& hierarchy) {
    const DebugBuffers debug(in.debugDir, "pcss");
    if (!debug.enabled()) return;
    writeDepthMap(debug, "depth", soft.map);
    const GBuffer& g = in.gbuffer;
    debug.write("blocker-distance", g.width, g.height, b.blockerDistance, float(soft.zNear()), float(soft.zFar()));
    const float widest = *std::max_element(b.widthTexels.begin(), b.widthTexels.end());
    debug.write("penumbra-width", g.width, g.height, b.widthTexels, 0.0f, std::max(widest, 1.0f));
    if (!hierarchy) return;
    writeMinMaxHierarchy(debug, *hierarchy);
    const float most = *std::max_element(b.knownTaps.begin(), b.knownTaps.end());
    debug.write("known-taps", g.width, g.height, b.knownTaps, 0.0f, std::max(most, 1.0f));
}

ShadowOutputs runPcss(const ShadowInputs& in) {
    const PcssSettings settings = pcssSettingsTable().read(in.params);
    requireAreaLight(in.light, "pcss");
    if (!anyReachable(in.gbuffer, in.light)) return unlitOutputs(in.gbuffer);   // settings checked first
    StageTimer timer;
    const SoftShadowMap& soft = renderPcssMap(in, settings.resolution);
    timer.lap("map");
    const std::optional<MinMaxHierarchy> hierarchy = pcssHierarchy(soft, settings);
    timer.lap("hierarchy");
    const PcssBuffers b = pcssPerPixel(in, soft, settings, hierarchy);
    timer.lap("receivers");
    writeDebug(in, soft, b, hierarchy);
    // Figures in pixel order (one thread): the same for any thread count.
    size_t penumbra = 0;
    double widthSum = 0.0;
    for (size_t k = 0; k < b.widthTexels.size(); ++k) {
        if (b.blockerDistance[k] > 0.0f) ++penumbra, widthSum += b.widthTexels[k];
    }
    ShadowOutputs out;
    out.visibility = b.visibility;
    out.stats = {{"resolution_texels", double(settings.resolution)},
                 {"light_width_at_1m_texels", 0.5 * (soft.lightTexels.x + soft.lightTexels.y)},
                 {"blocker_pixels", double(penumbra)},
                 {"mean_filter_width_texels", penumbra ? widthSum / double(penumbra) : 0.0},
                 {"light_near_m", soft.zNear()},
                 {"light_far_m", soft.zFar()}};
    if (settings.minMaxHierarchy) out.stats.push_back({"hierarchy_known_taps_percent", b.knownTapsPercent});
    timer.appendTo(out.stats);
    return out;
}

}  // namespace

const SettingsTable<PcssSettings>& pcssSettingsTable() {
    using S = PcssSettings;
    static const auto table =
        SettingsTable<S>()
            .include(member(&S::resolution), mapResolutionTable("texels per side of the map"))
            .include(member(&S::search), blockerSearchSettingsTable())
            .integer("filter-taps", member(&S::filterTaps), 1, 128, "PCF: Poisson taps over the eq. 7.6 width")
            .flag("min-max-hierarchy", member(&S::minMaxHierarchy),
                  "skip the taps the map's min/max depth hierarchy proves lit or shadowed (same V)")
            .choice("rotation", member(&S::rotation), rotationNoiseChoices(),
                    "what turns the search and filter disks per pixel");
    return table;
}

const SoftShadowMap& renderPcssMap(const ShadowInputs& in, int resolution) {
    return renderSoftShadowMap(in, resolution, polygonOffsetFor(BiasSettings{}), kSearchFitMarginTexels, true);
}

// The three steps per camera pixel in float, through the shadow lookup's vector kernel
// (shadows/maps/lookup_kernel.inl, filter kLookupPcss).
std::optional<MinMaxHierarchy> pcssHierarchy(const SoftShadowMap& soft, const PcssSettings& settings) {
    if (!settings.minMaxHierarchy) return std::nullopt;
    return std::optional<MinMaxHierarchy>(std::in_place, soft.map);
}

PcssBuffers pcssPerPixel(const ShadowInputs& in, const SoftShadowMap& soft, const PcssSettings& settings,
                         const std::optional<MinMaxHierarchy>& hierarchy) {
    const GBuffer& g = in.gbuffer;
    const PcfKernel searchDisk = makePcfKernel({FilterKind::Poisson, 3, settings.search.taps, 1.0});
    // The lookup turns both disks by the filter's rotation.
    const PcfKernel filterDisk =
        makePcfKernel({FilterKind::Poisson, 3, settings.filterTaps, 1.0, settings.rotation}, in.frameIndex);
    const LookupPass pass(soft.map, soft.light,
                          {searchDisk, settings.search.region, filterDisk, soft.lightTexels,
                           hierarchy ? &hierarchy->forKernel() : nullptr},
                          in.simd);
    const size_t n = g.pixelCount();
    PcssBuffers out{std::vector<float>(n), std::vector<float>(n), std::vector<float>(n),
                    std::vector<float>(hierarchy ? n : 0)};
    lookUpEveryRow(g, pass, {out.visibility.data(), out.blockerDistance.data(), out.widthTexels.data(),
                             hierarchy ? out.knownTaps.data() : nullptr});
    if (hierarchy) out.knownTapsPercent = knownTapsPercent(out, settings);
    return out;
}

Technique pcssTechnique() {
    return {.name = "pcss",
            .description = "percentage-closer soft shadows (RTR 7.6, Fernando 2005): blocker search, eq. 7.6 "
                           "width, Poisson PCF",
            .params = pcssSettingsTable().specs(),
            .run = runPcss,
            .referenceName = "reference-soft",
            .output = TechniqueOutput::Visibility};
}

}  // namespace shadowlab
