#include "app/plots/line_plot.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/vec2.hpp>

#include "app/plots/svg.h"

namespace shadowlab {
namespace {

using svg::Axis;
using svg::format;
using svg::kCanvasHeight, svg::kCanvasWidth, svg::kPlotBottom, svg::kPlotLeft, svg::kPlotTop;

constexpr double kLinePlotRight = 620;   // the legend sits right of the plot
// One legend row per series, its name from kLegendText on. 8 units a character covers
// 12-unit DejaVu Sans, Debian's sans-serif (digits and most letters 7.6, '=' 10).
constexpr double kLegendRow = 18, kLegendText = kLinePlotRight + 46, kLegendCharWidth = 8;

// The canvas widens for long series names (a fly-through's are its settings) and deepens
// for many series, so that no legend entry is cut off.
glm::dvec2 canvasSize(const LinePlot& plot) {
    size_t longest = 0;
    for (const PlotSeries& s : plot.series) longest = std::max(longest, s.name.size());
    return {std::max(kCanvasWidth, kLegendText + kLegendCharWidth * double(longest) + 10),
            std::max(kCanvasHeight, kPlotTop + 10 + kLegendRow * double(plot.series.size()))};
}

void requireValid(const LinePlot& plot) {
    size_t points = 0;
    for (const PlotSeries& s : plot.series) {
        if (s.x.size() != s.y.size() || (!s.labels.empty() && s.labels.size() != s.x.size())) {
            throw std::invalid_argument("line plot: series '" + s.name + "' has mismatched lengths");
        }
        for (size_t k = 0; k < s.x.size(); ++k) {
            if (!(s.x[k] >= 0.0 && s.y[k] >= 0.0) || !std::isfinite(s.x[k]) || !std::isfinite(s.y[k])) {
                throw std::invalid_argument("line plot: series '" + s.name + "' has a negative or non-finite value");
            }
        }
        points += s.x.size();
    }
    if (points == 0) throw std::invalid_argument("line plot: no points");
}

}  // namespace

std::string formatLinePlotSvg(const LinePlot& plot) {
    requireValid(plot);
    double largestX = 0.0, largestY = 0.0;
    for (const PlotSeries& s : plot.series) {
        for (double x : s.x) largestX = std::max(largestX, x);
        for (double y : s.y) largestY = std::max(largestY, y);
    }
    const Axis ax(largestX), ay(1.05 * largestY);
    const auto X = [&](double x) { return kPlotLeft + x / ax.top * (kLinePlotRight - kPlotLeft); };
    const auto Y = [&](double y) { return kPlotBottom - y / ay.top * (kPlotBottom - kPlotTop); };
    const glm::dvec2 canvas = canvasSize(plot);
    std::string text = format(R"(<svg xmlns="http://www.w3.org/2000/svg" width="%.0f" height="%.0f" )"
                              R"(viewBox="0 0 %.0f %.0f" font-family="sans-serif" font-size="12">)" "\n",
                              canvas.x, canvas.y, canvas.x, canvas.y);
    text += format(R"(<rect width="%.0f" height="%.0f" fill="#fff"/>)" "\n", canvas.x, canvas.y);
    text += format(R"(<text x="%.1f" y="24" font-size="14">%s</text>)" "\n", kPlotLeft,
                   svg::escape(plot.title).c_str());
    text += format(R"(<rect x="%.1f" y="%.1f" width="%.1f" height="%.1f" fill="none" stroke="#444"/>)" "\n", kPlotLeft,
                   kPlotTop, kLinePlotRight - kPlotLeft, kPlotBottom - kPlotTop);
    for (double x = 0.0; x <= ax.top * (1 + 1e-9); x += ax.step) {
        text += format(R"(<line x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="#ddd"/>)" "\n", X(x), kPlotTop, X(x),
                       kPlotBottom);
        text += format(R"(<text x="%.1f" y="%.1f" text-anchor="middle">%g</text>)" "\n", X(x), kPlotBottom + 16, x);
    }
    for (double y = 0.0; y <= ay.top * (1 + 1e-9); y += ay.step) {
        text += format(R"(<line x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="#ddd"/>)" "\n", kPlotLeft, Y(y),
                       kLinePlotRight, Y(y));
        text += format(R"(<text x="%.1f" y="%.1f" text-anchor="end">%g</text>)" "\n", kPlotLeft - 6, Y(y) + 4, y);
    }
    text += format(R"(<text x="%.1f" y="%.1f" text-anchor="middle">%s</text>)" "\n", (kPlotLeft + kLinePlotRight) / 2,
                   kPlotBottom + 40, svg::escape(plot.xTitle).c_str());
    text += format(R"svg(<text transform="translate(18 %.1f) rotate(-90)" text-anchor="middle">%s</text>)svg" "\n",
                   (kPlotTop + kPlotBottom) / 2, svg::escape(plot.yTitle).c_str());
    std::vector<svg::LabelBox> placed;
    for (size_t i = 0; i < plot.series.size(); ++i) {
        const PlotSeries& s = plot.series[i];
        const char* colour = svg::kPalette[i % std::size(svg::kPalette)];
        std::string points;
        for (size_t k = 0; k < s.x.size(); ++k) points += format("%.1f,%.1f ", X(s.x[k]), Y(s.y[k]));
        text += format(R"(<polyline class="series" fill="none" stroke="%s" stroke-width="1.5" points="%s"/>)" "\n",
                       colour, points.c_str());
        for (size_t k = 0; k < s.x.size(); ++k) {
            text += format(
                R"(<circle class="point" cx="%.1f" cy="%.1f" r="3.5" fill="%s"><title>%s: %g, %g</title></circle>)"
                "\n", X(s.x[k]), Y(s.y[k]), colour, svg::escape(s.name).c_str(), s.x[k], s.y[k]);
            if (!s.labels.empty()) text += svg::label(X(s.x[k]), Y(s.y[k]), s.labels[k], placed, kPlotTop, kPlotBottom);
        }
        const double legendY = kPlotTop + 10 + kLegendRow * double(i);
        text += format(R"(<line x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="%s" stroke-width="2"/>)" "\n",
                       kLinePlotRight + 20, legendY - 4, kLinePlotRight + 40, legendY - 4, colour);
        text += format(R"(<text x="%.1f" y="%.1f">%s</text>)" "\n", kLegendText, legendY, svg::escape(s.name).c_str());
    }
    return text + "</svg>\n";
}

}  // namespace shadowlab
