#include "app/plots/flythrough_plot.h"

#include <cmath>
#include <optional>

#include "app/plots/line_plot.h"

namespace shadowlab {
namespace {

// The plotted value of a frame, or nullopt where it has none (flicker on frame 0).
std::optional<double> plotted(const FlythroughFrame& frame, FlythroughPlot plot) {
    switch (plot) {
        case FlythroughPlot::Time: return frame.medianMs;
        case FlythroughPlot::Error: return frame.errors.rms;
        case FlythroughPlot::Flicker: return frame.flicker ? std::optional(frame.flicker->mean) : std::nullopt;
    }
    return std::nullopt;
}

}  // namespace

std::string formatFlythroughSvg(const FlythroughResults& results, FlythroughPlot plot) {
    static constexpr const char* kTitles[] = {"technique time (median ms)", "RMS of V against the reference",
                                              "flicker: mean |V_t - V_t-1| where the reference is unchanged"};
    const char* yTitle = kTitles[int(plot)];
    LinePlot linePlot{results.scene + ": " + yTitle + " along the path", "frame", yTitle, {}};
    for (const FlythroughSeries& s : results.series) {
        PlotSeries& line = linePlot.series.emplace_back(PlotSeries{s.label(), {}, {}, {}});
        for (const FlythroughFrame& f : s.frames) {
            const std::optional<double> y = plotted(f, plot);
            if (!y || !std::isfinite(*y)) continue;
            line.x.push_back(f.frame);
            line.y.push_back(*y);
        }
    }
    return formatLinePlotSvg(linePlot);
}

}  // namespace shadowlab
