// The filtered shadow maps `vsm`, `esm`, `evsm` and `msm` (Real-Time Rendering, 4th ed.,
// section 7.7): one mechanism, parameterised by the moments it stores (moments.h; each
// kind in the file named after its technique, vsm.cpp, esm.cpp, evsm.cpp, msm.cpp):
//
//   1. the depth map from the light's centre, in linear depth (soft_shadow_map.h);
//   2. every texel's moments (moments.h);
//   3. filtering (moment_filter.h): a separable box or Gaussian blur of a fixed width, or a
//      summed-area table that serves a box of any width per pixel;
//   4. per camera pixel, the filtered moments at the receiver and its linear depth t give V.
//
// width=pcss widens the box per pixel as PCSS would (RTR 7.7: "These filtered approaches
// can all be used in conjunction with PCSS to provide variable-width penumbrae"; Lauritzen,
// GPU Gems 3 ch. 8; Annen et al. 2008, section 5): PCSS's blocker search (blocker_search.h,
// in the shadow lookup's vector kernel) and eq. 7.6 give the width, and the summed-area
// table the box, so it needs filter=sat. A fixed width is a constant penumbra, as PCF's (RTR 7.5).
//
// Every stage runs rows in parallel with one owner per output value and fixed summation
// orders, so V is the same bytes for any thread count.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "raster/portable_math.h"
#include "shadows/debug_buffers.h"
#include "shadows/filtered/blocker_search.h"
#include "shadows/filtered/moment_filter.h"
#include "shadows/filtered/soft_shadow_techniques.h"
#include "shadows/maps/pcf.h"
#include "shadows/maps/shadow_lookup.h"
#include "shadows/maps/shadow_map_debug.h"
#include "shadows/stage_timer.h"

namespace shadowlab {
namespace {

// The summed-area table must give V to within 2^-10 (a quarter of an 8-bit step).
constexpr double kSatRelativeErrorLimit = 0x1p-10;
// Fit margin beyond half the fixed width (or the blocker search's reach): the bilinear
// lookup reaches one more texel centre.
constexpr double kFitMarginTexels = 1.5;

struct FilteredSettings {
    int resolution = kSoftMapResolution;
    bool summedAreaTable = false;
    BlurKind blur = BlurKind::Box;
    int widthTexels = 7;
    bool pcssWidth = false;
    BlockerSearchSettings search;
    MomentSettings moments;
};

// The family's rows, then the kind's own.
SettingsTable<FilteredSettings> filteredSettingsTable(MomentKind kind) {
    using S = FilteredSettings;
    return SettingsTable<S>()
        .include(member(&S::resolution), mapResolutionTable("texels per side of the map"))
        .choice("filter", member(&S::summedAreaTable),
                {{"blur", false, "separable, fixed width"}, {"sat", true, "summed-area table, any width per pixel"}})
        .choice("blur", member(&S::blur),
                {{"box", BlurKind::Box}, {"gaussian", BlurKind::Gaussian, "sigma = width / 6"}}, "filter=blur")
        .integer("filter-width", member(&S::widthTexels), 1, int(kMaxBlurTaps), "fixed width: taps per side, odd")
        .choice("width", member(&S::pcssWidth),
                {{"fixed", false}, {"pcss", true, "blocker search and eq. 7.6 per pixel; needs filter=sat"}})
        .include(member(&S::search), blockerSearchSettingsTable())
        .include(member(&S::moments), momentSettingsTable(kind));
}

// The settings as read, of this kind, checked where the table's ranges cannot.
FilteredSettings checked(MomentKind kind, FilteredSettings s) {
    const std::string name = momentKindName(kind);
    s.moments.kind = kind;
    if (s.widthTexels % 2 == 0) throw std::invalid_argument(name + ": filter-width must be odd (taps centred on a texel)");
    if (s.pcssWidth && !s.summedAreaTable) {
        throw std::invalid_argument(name + ": width=pcss needs filter=sat (a box of a different width at every pixel)");
    }
    return s;
}

void checkTablePrecision(const FilteredSettings& s, const MomentMap& moments) {
    const double bound = satRelativeError(s.moments, moments);
    if (bound <= kSatRelativeErrorLimit) return;
    const double logRangeAllowed = portable::log(kSatRelativeErrorLimit / (bound / momentDynamicRange(s.moments)));
    throw std::invalid_argument(
        std::string(momentKindName(s.moments.kind)) + ": filter=sat cannot resolve V to 2^-10 with these exponents at " +
        std::to_string(moments.size) + "^2 texels (error bound " + std::to_string(bound) +
        ", moment_filter.h); the moments' range e^x needs x <= " + std::to_string(logRangeAllowed) +
        " (esm: exponent; evsm: 4 x the larger exponent)");
}

struct PixelBuffers {
    std::vector<float> visibility, widthTexels;
};

// A row's receivers on their way to V, one array per quantity: where each falls in the map,
// its filter width and depth (gathered pixel by pixel), then its filtered moments (looked up
// for the whole row in one loop, so the map reads of many receivers are in flight at once),
// then V.
struct ReceiverRow {
    std::vector<size_t> pixels;
    std::vector<glm::dvec2> texels, widths;
    std::vector<double> depths, moments, visibility;
    void clear() {   // for the next row, keeping the memory
        pixels.clear(), texels.clear(), widths.clear(), depths.clear(), moments.clear(), visibility.clear();
    }
};

// Step 4 for every pixel: the filtered moments at the receiver, then V, a row's receivers
// in one run of the kind's visibility (whose exponentials go a vector at a time).
PixelBuffers visibilityPerPixel(const ShadowInputs& in, const SoftShadowMap& soft, const FilteredSettings& s,
                                const MomentMap& blurred, const SummedAreaTable& table, std::vector<ReceiverRow>& rows) {
    const GBuffer& g = in.gbuffer;
    const size_t channels = size_t(momentCount(s.moments.kind));
    PixelBuffers out{std::vector<float>(g.pixelCount(), 0.0f), std::vector<float>(g.pixelCount(), 0.0f)};
    // width=pcss: steps 1 and 2 of PCSS for every pixel in the lookup's vector kernel
    // (lookup_kernel.inl, kLookupBlockerSearch), which leaves V = 1 where it finds no blocker.
    std::vector<float> blockerDistance(s.pcssWidth ? g.pixelCount() : 0);
    if (s.pcssWidth) {
        const PcfKernel search = makePcfKernel({FilterKind::Poisson, 3, s.search.taps, 1.0});
        const LookupPass pass(soft.map, soft.light, {search, s.search.region, soft.lightTexels}, in.simd);
        lookUpEveryRow(g, pass, {out.visibility.data(), blockerDistance.data()});
    }
    const auto perPixel = [&](ReceiverRow& row, size_t k, const glm::dvec3&, const glm::dvec3&,
                              const SoftReceiver& receiver) {
        glm::dvec2 width(s.widthTexels);
        if (s.pcssWidth) {
            if (blockerDistance[k] == 0.0f) return;   // no blocker: lit
            // Eq. 7.6 from d_o, kept within near .. d_r as the kernel keeps it (width 0 at contact).
            const double dr = receiver.distance;
            width = sampleWidthTexels(soft, dr, std::min(std::max(double(blockerDistance[k]), soft.zNear()), dr));
        }
        row.pixels.push_back(k);
        row.texels.push_back(receiver.texel);
        if (s.summedAreaTable) row.widths.push_back(width);   // the blur's width is fixed
        row.depths.push_back(soft.normalised(receiver.distance));
        out.widthTexels[k] = float(0.5 * (width.x + width.y));
    };
    const auto endOfRow = [&](ReceiverRow& row) {
        const size_t count = row.pixels.size();
        row.moments.resize(count * channels);
        if (s.summedAreaTable) {
            for (size_t r = 0; r < count; ++r) {
                boxMean(table, row.texels[r] - 0.5 * row.widths[r], row.texels[r] + 0.5 * row.widths[r], &row.moments[r * channels]);
            }
        } else {
            sampleBilinearRun(blurred, row.texels.data(), count, row.moments.data());
        }
        row.visibility.resize(count);
        momentVisibilityRun(s.moments, row.moments.data(), row.depths.data(), count, row.visibility.data(), in.simd);
        for (size_t r = 0; r < count; ++r) out.visibility[row.pixels[r]] = float(row.visibility[r]);
    };
    forEachReceiverFacingLight(g, soft, rows, perPixel, endOfRow);
    return out;
}

// One channel of a moment map as an image, black..white over its own range.
void writeChannel(const DebugBuffers& debug, const std::string& name, const MomentMap& m, int c) {
    std::vector<float> v(size_t(m.size) * size_t(m.size));
    for (size_t k = 0; k < v.size(); ++k) v[k] = float(m.values[k * size_t(m.channels) + size_t(c)]);
    const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
    debug.write(name, m.size, m.size, v, *lo, *hi);
}

void writeDebug(const ShadowInputs& in, const FilteredSettings& s, const SoftShadowMap& soft, const MomentMap& moments,
                const MomentMap& blurred, const SummedAreaTable& table, const PixelBuffers& px) {
    const DebugBuffers debug(in.debugDir, momentKindName(s.moments.kind));
    if (!debug.enabled()) return;
    writeDepthMap(debug, "depth", soft.map);
    debug.write("linear-depth", soft.map.size, soft.map.size, soft.linear, 0.0f, 1.0f);
    for (int c = 0; c < moments.channels; ++c) {
        writeChannel(debug, "moment" + std::to_string(c + 1), moments, c);
        if (!s.summedAreaTable) writeChannel(debug, "filtered" + std::to_string(c + 1), blurred, c);
    }
    if (s.summedAreaTable) {
        // The table of the first moment, (size + 1)^2 with its zero row and column.
        const MomentMap sat{table.size + 1, table.channels, table.sums};
        writeChannel(debug, "sat1", sat, 0);
    }
    const float widest = *std::max_element(px.widthTexels.begin(), px.widthTexels.end());
    debug.write("filter-width", in.gbuffer.width, in.gbuffer.height, px.widthTexels, 0.0f, std::max(widest, 1.0f));
}

// The moments, the filter's maps and the receivers' row buffers (one per thread), kept
// between frames (technique_history.h): each frame writes them over the last one's, so a
// steady state allocates none of them.
struct FilteredMaps {
    MomentMap moments, rowPass, blurred;   // rowPass: the blur's first pass
    SummedAreaTable table;
    std::vector<ReceiverRow> receiverRows;
};

ShadowOutputs runFiltered(const ShadowInputs& in, const FilteredSettings& s) {
    requireAreaLight(in.light, momentKindName(s.moments.kind));
    if (!anyReachable(in.gbuffer, in.light)) return unlitOutputs(in.gbuffer);   // settings checked first
    StageTimer timer;
    const SoftShadowMap& soft = renderSoftShadowMap(in, s.resolution, polygonOffsetFor(BiasSettings{}),
                                                   kFitMarginTexels + 0.5 * s.widthTexels, s.pcssWidth);
    timer.lap("map");
    FilteredMaps& maps = in.kept().state<FilteredMaps>();
    maps.moments = momentMap(soft, s.moments, in.simd, std::move(maps.moments));
    const MomentMap& moments = maps.moments;
    timer.lap("moments");
    if (s.summedAreaTable) {
        checkTablePrecision(s, moments);
        maps.table = summedAreaTable(moments, std::move(maps.table));
    } else {
        blurMoments(moments, blurWeights(s.blur, s.widthTexels), maps.rowPass, maps.blurred);
    }
    const MomentMap& blurred = maps.blurred;
    const SummedAreaTable& table = maps.table;
    timer.lap("filter");
    PixelBuffers px = visibilityPerPixel(in, soft, s, blurred, table, maps.receiverRows);
    timer.lap("receivers");
    writeDebug(in, s, soft, moments, blurred, table, px);
    ShadowOutputs out;
    out.visibility = std::move(px.visibility);   // the last use
    out.stats = {{"resolution_texels", double(s.resolution)},
                 {"moments_count", double(moments.channels)},
                 {"light_near_m", soft.zNear()},
                 {"light_far_m", soft.zFar()}};
    if (s.summedAreaTable) out.stats.push_back({"sat_error_bound_ratio", satRelativeError(s.moments, moments)});
    timer.appendTo(out.stats);
    return out;
}

}  // namespace

Technique filteredShadowMapTechnique(MomentKind kind) {
    const SettingsTable<FilteredSettings> table = filteredSettingsTable(kind);
    return {.name = momentKindName(kind),
            .description = momentKindDescription(kind),
            .params = table.specs(),
            .run = [kind, table](const ShadowInputs& in) {
                return runFiltered(in, checked(kind, table.read(in.params)));
            },
            .referenceName = "reference-soft",
            .output = TechniqueOutput::Visibility};
}

}  // namespace shadowlab
