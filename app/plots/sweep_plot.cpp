#include "app/plots/sweep_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <stdexcept>

#include "app/plots/svg.h"

namespace shadowlab {
namespace {

using svg::format;
using svg::kCanvasHeight, svg::kCanvasWidth, svg::kPlotBottom, svg::kPlotLeft, svg::kPlotTop;

constexpr double kSweepPlotRight = 600;   // the legend sits right of the plot

// Times below a microsecond (a technique that does nothing) are drawn at 1 us: a log axis
// has no place for 0.
constexpr double kMinPlottedMs = 1e-3;

struct Range {
    double lo, hi;
};

double plottedMs(const SweepRow& row) { return std::max(row.medianMs, kMinPlottedMs); }

// Whole decades around the times: log10 of the axis ends.
Range decadeRange(const std::vector<SweepRow>& rows) {
    Range r{INFINITY, -INFINITY};
    for (const SweepRow& row : rows) {
        r.lo = std::min(r.lo, std::floor(std::log10(plottedMs(row))));
        r.hi = std::max(r.hi, std::ceil(std::log10(plottedMs(row))));
    }
    if (r.hi <= r.lo) r.hi = r.lo + 1;
    return r;
}

struct Axes {
    Range decades;
    double errorStep, errorTop;
    double x(double ms) const {
        return kPlotLeft + (std::log10(std::max(ms, kMinPlottedMs)) - decades.lo) / (decades.hi - decades.lo) * (kSweepPlotRight - kPlotLeft);
    }
    double y(double error) const { return kPlotBottom - error / errorTop * (kPlotBottom - kPlotTop); }
};

Axes fitAxes(const std::vector<SweepRow>& rows, PlotErrorAxis axis) {
    double largest = 0.0;
    for (const SweepRow& row : rows) largest = std::max(largest, plottedError(row, axis));
    const double step = svg::niceTickStep(largest);
    // A little headroom, so that the worst point does not sit on the frame.
    return {decadeRange(rows), step, std::max(step, std::ceil(1.05 * largest / step) * step)};
}

// Ticks at 1, 2 and 5 times each power of ten when the axis spans few decades, else at
// the powers only.
std::vector<double> timeTicks(const Range& decades) {
    const bool fine = decades.hi - decades.lo <= 3;
    std::vector<double> ticks;
    for (double d = decades.lo; d <= decades.hi; ++d)
        for (double m : {1.0, 2.0, 5.0})
            if ((m == 1.0 || fine) && d + std::log10(m) <= decades.hi) ticks.push_back(m * std::pow(10.0, d));
    return ticks;
}

const char* axisTitle(PlotErrorAxis axis) {
    switch (axis) {
        case PlotErrorAxis::Rms: return "RMS error (V, or Y of a shaded image)";
        case PlotErrorAxis::RmsDisplay: return "RMS error of the displayed luminance";
        case PlotErrorAxis::Umbra: return "umbra errors, both ways (% of pixels)";
        case PlotErrorAxis::Flip: return "FLIP of the shaded image (mean)";
        case PlotErrorAxis::Auto:   // resolved before (resolvedPlotAxis)
        case PlotErrorAxis::Misclassified: break;
    }
    return "misclassified pixels (%)";
}

std::string axesSvg(const Axes& a, PlotErrorAxis axis) {
    std::string svg = format(R"(<rect x="%.1f" y="%.1f" width="%.1f" height="%.1f" fill="none" stroke="#444"/>)" "\n",
                             kPlotLeft, kPlotTop, kSweepPlotRight - kPlotLeft, kPlotBottom - kPlotTop);
    for (double ms : timeTicks(a.decades)) {
        const double x = a.x(ms);
        svg += format(R"(<line x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="#ddd"/>)" "\n", x, kPlotTop, x, kPlotBottom);
        svg += format(R"(<text x="%.1f" y="%.1f" text-anchor="middle">%g</text>)" "\n", x, kPlotBottom + 16, ms);
    }
    for (double e = 0.0; e <= a.errorTop * (1 + 1e-9); e += a.errorStep) {
        const double y = a.y(e);
        svg += format(R"(<line x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="#ddd"/>)" "\n", kPlotLeft, y, kSweepPlotRight, y);
        svg += format(R"(<text x="%.1f" y="%.1f" text-anchor="end">%g</text>)" "\n", kPlotLeft - 6, y + 4, e);
    }
    svg += format(R"(<text x="%.1f" y="%.1f" text-anchor="middle">technique median ms (log scale)</text>)" "\n",
                  (kPlotLeft + kSweepPlotRight) / 2, kPlotBottom + 40);
    svg += format(R"svg(<text transform="translate(18 %.1f) rotate(-90)" text-anchor="middle">%s</text>)svg" "\n",
                  (kPlotTop + kPlotBottom) / 2, axisTitle(axis));
    return svg;
}

// Right, then down: the best error reachable within each time.
std::string frontSvg(const SweepResults& results, const std::vector<size_t>& front, const Axes& a, PlotErrorAxis axis) {
    std::string points;
    for (size_t k = 0; k < front.size(); ++k) {
        const SweepRow& row = results.rows[front[k]];
        if (k > 0) points += format(" %.1f,%.1f", a.x(row.medianMs), a.y(plottedError(results.rows[front[k - 1]], axis)));
        points += format(" %.1f,%.1f", a.x(row.medianMs), a.y(plottedError(row, axis)));
    }
    std::string svg = R"(<polyline class="pareto-front" fill="none" stroke="#888" stroke-dasharray="4 3" points=")" +
                      points.substr(1) + "\"/>\n";
    for (size_t index : front) {
        const SweepRow& row = results.rows[index];
        svg += format(R"(<circle class="pareto" cx="%.1f" cy="%.1f" r="7" fill="none" stroke="#000"/>)" "\n",
                      a.x(row.medianMs), a.y(plottedError(row, axis)));
    }
    return svg;
}

size_t techniqueIndex(const SweepResults& results, const std::string& technique) {
    return size_t(std::ranges::find(results.techniques, technique) - results.techniques.begin());
}

// A row at its technique's defaults is labelled with the technique's name: "defaults"
// next to every point of a comparison of techniques would say nothing.
std::string rowLabel(const SweepRow& row, bool severalThreadCounts) {
    const std::string settings = row.settingsLabel();
    return (settings == "defaults" ? row.technique : settings) +
           (severalThreadCounts ? ", " + std::to_string(row.threads) + " thr" : "");
}

// Labels must not cover the legend or any point.
std::vector<svg::LabelBox> takenBoxes(const SweepResults& results, const Axes& a, PlotErrorAxis axis) {
    std::vector<svg::LabelBox> taken = {{kSweepPlotRight + 10, kPlotTop, kCanvasWidth, kPlotTop + 20.0 * double(results.techniques.size() + 1)}};
    for (const SweepRow& row : results.rows) {
        const double x = a.x(row.medianMs), y = a.y(plottedError(row, axis));
        taken.push_back({x - 4, y - 4, x + 4, y + 4});
    }
    return taken;
}

std::string pointsSvg(const SweepResults& results, const Axes& a, PlotErrorAxis axis,
                      const std::vector<std::string>& links) {
    std::set<int> threadCounts;
    for (const SweepRow& row : results.rows) threadCounts.insert(row.threads);
    std::string svg;
    std::vector<svg::LabelBox> placed = takenBoxes(results, a, axis);
    for (size_t k = 0; k < results.rows.size(); ++k) {
        const SweepRow& row = results.rows[k];
        const double x = a.x(row.medianMs), y = a.y(plottedError(row, axis));
        const std::string label = rowLabel(row, threadCounts.size() > 1);
        const std::string point = format(
            R"(<circle class="point" cx="%.1f" cy="%.1f" r="4" fill="%s"><title>%s %s: %.4g ms, %.4g</title></circle>)",
            x, y, svg::kPalette[techniqueIndex(results, row.technique) % std::size(svg::kPalette)],
            svg::escape(row.technique).c_str(), svg::escape(label).c_str(), row.medianMs, plottedError(row, axis));
        svg += (links.empty() ? point : "<a href=\"" + links[k] + "\">" + point + "</a>") + "\n";
        svg += svg::label(x, y, label, placed, kPlotTop, kPlotBottom);
    }
    return svg;
}

std::string legendSvg(const SweepResults& results) {
    std::string svg;
    double y = kPlotTop + 10;
    for (size_t k = 0; k < results.techniques.size(); ++k, y += 20) {
        svg += format(R"(<circle cx="%.1f" cy="%.1f" r="4" fill="%s"/>)" "\n", kSweepPlotRight + 20, y, svg::kPalette[k % std::size(svg::kPalette)]);
        svg += format(R"(<text x="%.1f" y="%.1f">%s</text>)" "\n", kSweepPlotRight + 30, y + 4, svg::escape(results.techniques[k]).c_str());
    }
    svg += format(R"(<circle cx="%.1f" cy="%.1f" r="7" fill="none" stroke="#000"/>)" "\n", kSweepPlotRight + 20, y);
    svg += format(R"(<text x="%.1f" y="%.1f">Pareto front</text>)" "\n", kSweepPlotRight + 30, y + 4);
    return svg;
}

}  // namespace

PlotErrorAxis parsePlotErrorAxis(const std::string& name) {
    if (name == "auto") return PlotErrorAxis::Auto;
    if (name == "misclassified") return PlotErrorAxis::Misclassified;
    if (name == "rms") return PlotErrorAxis::Rms;
    if (name == "umbra") return PlotErrorAxis::Umbra;
    if (name == "rms-display") return PlotErrorAxis::RmsDisplay;
    if (name == "flip") return PlotErrorAxis::Flip;
    throw std::invalid_argument("plot axis must be auto, misclassified, rms, umbra, rms-display or flip, got '" + name + "'");
}

PlotErrorAxis resolvedPlotAxis(PlotErrorAxis asked, const std::vector<SweepRow>& rows) {
    if (asked != PlotErrorAxis::Auto) return asked;
    const std::string hard = Technique{}.referenceName;
    return std::ranges::any_of(rows, [&](const SweepRow& row) { return row.reference == hard; })
               ? PlotErrorAxis::Misclassified
               : PlotErrorAxis::Rms;
}

void requirePlottable(const std::vector<SweepRow>& rows, PlotErrorAxis axis) {
    for (const SweepRow& row : rows) {
        if (axis == PlotErrorAxis::RmsDisplay && !row.errors.rmsDisplay)
            throw std::invalid_argument("--plot-y rms-display: " + row.technique +
                                        " is scored on V, which has no displayed luminance");
        if (axis == PlotErrorAxis::Flip && !row.errors.flipMean)
            throw std::invalid_argument("--plot-y flip: " + row.technique + " has no FLIP figure (JSON written before it)");
    }
}

double plottedError(const SweepRow& row, PlotErrorAxis axis) {
    const ErrorFigures& e = row.errors;
    switch (axis) {
        case PlotErrorAxis::Rms: return e.rms;
        case PlotErrorAxis::RmsDisplay: return e.rmsDisplay.value();   // requirePlottable first
        case PlotErrorAxis::Umbra: return e.percentOfPixels(e.umbraErrors());
        case PlotErrorAxis::Flip: return e.flipMean.value();   // requirePlottable first
        case PlotErrorAxis::Auto:   // a row alone cannot choose: callers resolve (resolvedPlotAxis)
        case PlotErrorAxis::Misclassified: break;
    }
    return e.percentOfPixels(e.misclassified());
}

std::vector<size_t> paretoFront(const std::vector<SweepRow>& rows, PlotErrorAxis asked) {
    const PlotErrorAxis axis = resolvedPlotAxis(asked, rows);
    std::vector<size_t> order(rows.size());
    for (size_t k = 0; k < order.size(); ++k) order[k] = k;
    // Faster first, then lower error, then earlier row: each row is on the front exactly
    // when its error is below that of every row before it in this order.
    std::ranges::stable_sort(order, [&](size_t a, size_t b) {
        if (rows[a].medianMs != rows[b].medianMs) return rows[a].medianMs < rows[b].medianMs;
        return plottedError(rows[a], axis) < plottedError(rows[b], axis);
    });
    std::vector<size_t> front;
    for (size_t index : order)
        if (front.empty() || plottedError(rows[index], axis) < plottedError(rows[front.back()], axis)) front.push_back(index);
    return front;
}

std::string formatSweepSvg(const SweepResults& results, PlotErrorAxis asked, const std::vector<std::string>& links) {
    if (results.rows.empty()) throw std::invalid_argument("sweep plot: no rows");
    const PlotErrorAxis axis = resolvedPlotAxis(asked, results.rows);
    if (!links.empty() && links.size() != results.rows.size())
        throw std::invalid_argument("sweep plot: one link per row");
    const Axes a = fitAxes(results.rows, axis);
    std::string svg = format(R"(<svg xmlns="http://www.w3.org/2000/svg" width="%.0f" height="%.0f" viewBox="0 0 %.0f %.0f" font-family="sans-serif" font-size="12">)" "\n",
                             kCanvasWidth, kCanvasHeight, kCanvasWidth, kCanvasHeight);
    svg += format(R"(<rect width="%.0f" height="%.0f" fill="#fff"/>)" "\n", kCanvasWidth, kCanvasHeight);
    svg += format(R"(<text x="%.1f" y="24" font-size="14">%s: speed against error</text>)" "\n", kPlotLeft,
                  svg::escape(results.scene).c_str());
    svg += axesSvg(a, axis);
    svg += frontSvg(results, paretoFront(results.rows, axis), a, axis);
    svg += pointsSvg(results, a, axis, links);
    svg += legendSvg(results);
    return svg + "</svg>\n";
}

}  // namespace shadowlab
