// The `izb` technique: the irregular z-buffer's stages (izb.h) in order, its figures and its
// debug buffers.
#include <algorithm>
#include <optional>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include "shading/lights.h"
#include "shadows/debug_buffers.h"
#include "shadows/izb/izb.h"
#include "shadows/ray_offset.h"
#include "shadows/stage_timer.h"

namespace shadowlab {
namespace {

// Mean non-empty list length chooseResolution() aims at: one to four receivers per list
// keep both the lists and the grid small; two is the middle of that range.
constexpr double kTargetListLength = 2.0;

// Calls visit(texel number, image index) for every texel of the grid, the image index
// counting row by row with the views stacked vertically (the debug images' layout).
template <class Visit>
void forEachTexel(const izb::LightGrid& grid, Visit visit) {
    const int R = grid.resolution;
    size_t pixel = 0;
    for (int view = 0; view < int(grid.views.size()); ++view) {
        for (int j = 0; j < R; ++j) {
            for (int i = 0; i < R; ++i) visit(grid.texelIndex(view, i, j), pixel++);
        }
    }
}

// Length figures over the texels' lists: longest, mean and 99th percentile (nearest rank) of
// the non-empty ones, and how many are empty.
// How many texels hold each list length, counted over ranges of texels in parallel and
// summed (integers: the same for any schedule).
using Histogram = std::vector<uint64_t>;
Histogram lengthHistogram(const izb::TexelLists& lists, size_t texels) {
    const auto count = [&](const tbb::blocked_range<size_t>& range, Histogram histogram) {
        for (size_t t = range.begin(); t != range.end(); ++t) {
            const uint32_t n = lists.length(t);
            if (histogram.size() <= n) histogram.resize(n + 1, 0);
            ++histogram[n];
        }
        return histogram;
    };
    const auto add = [](Histogram a, const Histogram& b) {
        if (a.size() < b.size()) a.resize(b.size(), 0);
        for (size_t n = 0; n < b.size(); ++n) a[n] += b[n];
        return a;
    };
    return tbb::parallel_reduce(tbb::blocked_range<size_t>(0, texels, 1 << 16), Histogram(1, 0), count, add);
}

void addListStats(const izb::LightGrid& grid, const izb::TexelLists& lists, std::vector<TechniqueStat>& stats) {
    Histogram histogram = lengthHistogram(lists, grid.texelCount());
    // The numbers past the resolution in the edge tiles are no texels (and always empty).
    const uint64_t texels = uint64_t(grid.views.size()) * uint64_t(grid.resolution) * uint64_t(grid.resolution);
    histogram[0] -= grid.texelCount() - texels;
    const uint64_t nonEmpty = texels - histogram[0];
    // Nearest rank: the shortest length L with at least 99% of the non-empty lists <= L.
    uint64_t p99 = 0, seen = 0;
    for (size_t n = 1; n < histogram.size() && 100 * seen < 99 * nonEmpty; ++n) seen += histogram[n], p99 = n;
    stats.push_back({"list_max_receivers", double(histogram.size() - 1)});
    stats.push_back({"list_mean_nonempty_receivers", nonEmpty ? double(lists.entry.size()) / double(nonEmpty) : 0.0});
    stats.push_back({"list_p99_nonempty_receivers", double(p99)});
    stats.push_back({"empty_texels", double(histogram[0])});
    stats.push_back({"empty_texels_percent", 100.0 * double(histogram[0]) / double(texels)});
}

void writeDebugBuffers(const ShadowInputs& in, const izb::LightGrid& grid, const izb::TexelLists& lists,
                       const izb::Occlusion& occlusion) {
    const DebugBuffers debug(in.debugDir, "izb");
    if (!debug.enabled()) return;
    const int width = grid.resolution, height = int(grid.views.size()) * grid.resolution;
    const size_t pixels = size_t(width) * size_t(height);
    std::vector<float> length(pixels), occupied(pixels), occluders(pixels);
    float longest = 0.0f, most = 0.0f;
    forEachTexel(grid, [&](size_t t, size_t pixel) {
        length[pixel] = float(lists.length(t));
        occupied[pixel] = lists.length(t) > 0 ? 1.0f : 0.0f;
        occluders[pixel] = float(occlusion.occluders[t]);
        longest = std::max(longest, length[pixel]), most = std::max(most, occluders[pixel]);
    });
    debug.write("list-length", width, height, length, 0.0f, longest);
    debug.write("occupancy", width, height, occupied, 0.0f, 1.0f);
    debug.write("occluders", width, height, occluders, 0.0f, most);
}

}  // namespace

const SettingsTable<IzbSettings>& izbSettingsTable() {
    static const auto table = SettingsTable<IzbSettings>().integerOrAuto(
        "resolution", member(&IzbSettings::resolution), kMinMapResolution, kMaxMapResolution,
        "light grid texels per side; auto: a mean of about 2 receivers per non-empty texel");
    return table;
}

ShadowOutputs runIrregularZBuffer(const ShadowInputs& in, const IzbSettings& settings) {
    const Light light = pointLightFor(in.light);
    const double diagonal = sceneDiagonal(in.receiverWorld());
    ShadowOutputs out;
    StageTimer timer;
    const izb::Receivers receivers = izb::gatherReceivers(in.gbuffer, light, diagonal, out.visibility, in.simd);
    out.stats.push_back({"receiver_pixels", double(receivers.size())});
    timer.lap("receivers");
    if (receivers.size() == 0) {
        timer.appendTo(out.stats);
        return out;
    }

    std::vector<LightView> views = izb::fitViews(light, in.gbuffer, in.casterWorld(), in.simd);
    const izb::ReceiverPlaces places = izb::placeReceivers(views, receivers);
    const int resolution =
        settings.resolution ? *settings.resolution : izb::chooseResolution(views.size(), places, kTargetListLength);
    const izb::LightGrid grid = izb::makeLightGrid(std::move(views), resolution, diagonal);
    out.stats.push_back({"resolution_texels", double(grid.resolution)});
    out.stats.push_back({"views_count", double(grid.views.size())});
    timer.lap("light_grid");

    const izb::TexelLists lists = izb::buildTexelLists(izb::receiverTexels(grid.resolution, places), grid.texelCount());
    const izb::ListedReceivers listed = izb::listReceivers(receivers, lists);
    addListStats(grid, lists, out.stats);
    timer.lap("lists");

    const izb::ProjectedOccluders occluders = izb::projectOccluders(grid, in.casterWorld());
    const izb::TileBins bins = izb::binOccluders(grid, lists, occluders);
    out.stats.push_back({"tile_triangle_pairs_count", double(bins.triangles.entry.size())});
    timer.lap("binning");

    // Cut-outs are alpha-tested where a segment meets them; a world without any skips the test.
    std::optional<CasterTransmission> cutOuts;
    if (!in.casterWorld().cutOuts.empty()) cutOuts.emplace(in.casters().scene(), in.casterWorld());
    const izb::Occlusion occlusion = izb::traverseOccluders(grid, homogeneousLight(light), listed, lists, bins, occluders,
                                                            cutOuts ? &*cutOuts : nullptr, in.simd);
    for (size_t e = 0; e < listed.size(); ++e) {
        if (occlusion.blocked[e]) out.visibility[listed.pixel[e]] = 0.0f;
    }
    out.stats.push_back({"texel_triangle_pairs_count", double(occlusion.texelPairs)});
    out.stats.push_back({"segment_tests_count", double(occlusion.segmentTests)});
    if (cutOuts) out.stats.push_back({"cut_out_hits_count", double(occlusion.cutOutHits)});
    timer.lap("traversal");
    timer.appendTo(out.stats);
    writeDebugBuffers(in, grid, lists, occlusion);
    return out;
}

Technique irregularZBufferTechnique() {
    return {.name = "izb",
            .description = "irregular z-buffer: occluders rasterized at the camera's samples, exact hard shadows",
            .params = izbSettingsTable().specs(),
            .run = [](const ShadowInputs& in) { return runIrregularZBuffer(in, izbSettingsTable().read(in.params)); },
            .referenceName = "reference",
            .output = TechniqueOutput::Visibility};
}

}  // namespace shadowlab
