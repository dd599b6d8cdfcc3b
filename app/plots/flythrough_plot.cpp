#include "app/plots/flythrough_plot.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "app/plots/line_plot.h"

namespace shadowlab {
namespace {

std::optional<double> stat(const FlythroughFrame& frame, const char* name) {
    const auto found = std::ranges::find(frame.stats, name, &TechniqueStat::name);
    return found == frame.stats.end() ? std::nullopt : std::optional(found->value);
}

// The plotted value of a frame, or nullopt where it has none (flicker on frame 0, a stat
// the technique does not report).
std::optional<double> plotted(const FlythroughFrame& frame, FlythroughPlot plot) {
    switch (plot) {
        case FlythroughPlot::Time: return frame.medianMs;
        case FlythroughPlot::Error: return frame.errors.rms;
        case FlythroughPlot::Flicker: return frame.flicker ? std::optional(frame.flicker->mean) : std::nullopt;
        case FlythroughPlot::DrawnPages: return stat(frame, "cache_drawn_pages");
        case FlythroughPlot::CacheHits: return stat(frame, "cache_hit_percent");
        case FlythroughPlot::Flip: return frame.errors.flipMean;
    }
    return std::nullopt;
}

}  // namespace

bool hasFlythroughPlot(const FlythroughResults& results, FlythroughPlot plot) {
    return std::ranges::any_of(results.series, [&](const FlythroughSeries& s) {
        return std::ranges::any_of(s.frames, [&](const FlythroughFrame& f) { return plotted(f, plot).has_value(); });
    });
}

std::string formatFlythroughSvg(const FlythroughResults& results, FlythroughPlot plot) {
    static constexpr const char* kTitles[] = {"technique time (median ms)", "RMS of V against the reference",
                                              "flicker: mean |V_t - V_t-1| where the reference is unchanged",
                                              "pages drawn (cache_drawn_pages)", "cache hits (% of requested pages)",
                                              "FLIP of the shaded image against the reference (mean)"};
    const char* yTitle = kTitles[int(plot)];
    LinePlot linePlot{results.scene + ": " + yTitle + " along the path", "frame", yTitle, {}};
    for (const FlythroughSeries& s : results.series) {
        PlotSeries line{s.label(), {}, {}, {}};
        for (const FlythroughFrame& f : s.frames) {
            const std::optional<double> y = plotted(f, plot);
            if (!y || !std::isfinite(*y)) continue;
            line.x.push_back(f.frame);
            line.y.push_back(*y);
        }
        // A series without the stat at all (a plain map on the cache plots) is no line.
        const bool cachePlot = plot == FlythroughPlot::DrawnPages || plot == FlythroughPlot::CacheHits;
        if (!cachePlot || !line.x.empty()) linePlot.series.push_back(std::move(line));
    }
    return formatLinePlotSvg(linePlot);
}

}  // namespace shadowlab
